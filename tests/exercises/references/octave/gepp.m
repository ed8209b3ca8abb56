% A correct student solution of `numlab exercise` gepp in Octave (7 or later): Gaussian
% elimination with partial pivoting by hand (no \, lu or inv), its singular test and its pivot trace.
1;

function reply = solve(request)
  a = request.A;
  b = request.b(:);
  n = numel(b);
  negligible = n * eps * max(abs(a(:)));
  trace = struct('column', {}, 'pivot_row', {}, 'pivot', {});
  reply = struct();
  for k = 1:n
    [~, offset] = max(abs(a(k:n, k)));  % the largest |a_pk|, the first on a tie
    p = k - 1 + offset;
    a([k, p], :) = a([p, k], :);
    b([k, p]) = b([p, k]);
    if abs(a(k, k)) <= negligible
      reply.status = 'singular';
      reply.trace = num2cell(trace);  % a cell: a list even with one entry
      return;
    end
    trace(end + 1) = struct('column', k - 1, 'pivot_row', p - 1, 'pivot', a(k, k));
    for i = k + 1:n
      l = a(i, k) / a(k, k);
      a(i, k:n) -= l * a(k, k:n);
      b(i) -= l * b(k);
    end
  end
  x = zeros(n, 1);
  for i = n:-1:1
    x(i) = (b(i) - a(i, i + 1:n) * x(i + 1:n)) / a(i, i);
  end
  reply.x = num2cell(x');  % a cell: a list even when n = 1
  reply.trace = num2cell(trace);  % a cell: a list even with one entry
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
