% A correct student solution of `numlab exercise` polyfit in Octave (7 or later): least squares by
% the QR factorisation of the Vandermonde matrix with unit-length columns, lowest power first.
1;

function reply = solve(request)
  x = request.x(:);
  y = request.y(:);
  degree = request.degree;
  reply = struct();
  if numel(unique(x)) < degree + 1
    reply.status = 'singular';
    return;
  end
  V = ones(numel(x), degree + 1);  % row i: 1, x_i, ..., x_i^D
  for k = 2:degree + 1
    V(:, k) = V(:, k - 1) .* x;
  end
  scale = sqrt(sum(V .^ 2, 1));
  [Q, R] = qr(V ./ scale, 0);
  b = (R \ (Q' * y))' ./ scale;
  reply.coefficients = num2cell(b);
end

% JSON with every digit: Octave 7's jsonencode writes numbers below about 1e-15 as 0. Numbers with
% 17 significant digits (NaN and Inf as null), vectors as lists, matrices as lists of rows, cells
% and struct arrays as lists, structs as objects. A 1x1 value cannot say whether it is a list: a
% 1x1 struct array is an object and a 1x1 vector a number, so lists that may have one entry are
% sent as cells (num2cell).
function text = to_json(value)
  if isstruct(value) && isscalar(value)
    names = fieldnames(value);
    parts = cell(1, numel(names));
    for k = 1:numel(names)
      parts{k} = [jsonencode(names{k}), ':', to_json(value.(names{k}))];
    end
    text = ['{', strjoin(parts, ','), '}'];
  elseif isstruct(value) || iscell(value)
    if isstruct(value)
      value = num2cell(value);
    end
    parts = cellfun(@to_json, reshape(value, 1, []), 'UniformOutput', false);
    text = ['[', strjoin(parts, ','), ']'];
  elseif ischar(value)
    text = jsonencode(value);
  elseif islogical(value) && isscalar(value)
    text = ifelse_text(value, 'true', 'false');
  elseif isscalar(value)
    text = json_number(value);
  elseif isvector(value) || isempty(value)
    text = ['[', strjoin(arrayfun(@json_number, reshape(value, 1, []), 'UniformOutput', false), ','), ']'];
  else
    rows = arrayfun(@(i) to_json(value(i, :)), 1:size(value, 1), 'UniformOutput', false);
    text = ['[', strjoin(rows, ','), ']'];
  end
end

function text = ifelse_text(condition, yes, no)
  if condition
    text = yes;
  else
    text = no;
  end
end

function text = json_number(v)
  if isfinite(v)
    text = sprintf('%.17g', double(v));
  else
    text = 'null';
  end
end

% One request per line on stdin, one reply per line on stdout. input('', 's') reads a line as soon
% as it arrives (fgetl(stdin) on a pipe waits for it to fill or close); at the end of stdin it raises.
while true
  try
    line = input('', 's');
  catch
    break;
  end
  if isempty(strtrim(line))
    continue;
  end
  request = jsondecode(line);
  try
    reply = solve(request);
  catch err  % the checker reports it as this check's failure
    reply = struct('error', err.message);
  end
  reply.id = request.id;
  fputs(stdout, [to_json(reply), "\n"]);
  fflush(stdout);
end
