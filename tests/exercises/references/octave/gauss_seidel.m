% A correct student solution of `numlab exercise` gauss-seidel in Octave (7 or later): Gauss-Seidel
% sweeps by hand of M x = c, M = A or A'A, the stop test with abs, and the sweep trace.
1;

function reply = solve(request)
  m = request.A;
  c = request.b(:);
  if request.normal_equations
    c = m' * c;
    m = m' * m;
  end
  x = request.x0(:);
  tolerance = request.tolerance;
  max_iterations = request.max_iterations;
  n = numel(x);
  trace = struct('x', {}, 'update_inf', {});
  status = 'max_iterations';
  first_update = 0;
  sweep = 0;
  while sweep < max_iterations
    sweep += 1;
    old = x;
    for i = 1:n
      others = m(i, 1:i - 1) * x(1:i - 1) + m(i, i + 1:n) * x(i + 1:n);
      x(i) = (c(i) - others) / m(i, i);
    end
    update = max(abs(x - old));
    if sweep == 1
      first_update = update;
    end
    trace(end + 1) = struct('x', {num2cell(x')}, 'update_inf', update);
    if update <= tolerance * max(1, max(abs(x)))
      status = 'converged';
      break;
    end
    if update > 1e8 * max(first_update, tolerance)
      status = 'diverged';
      break;
    end
  end
  reply = struct('status', status, 'iterations', sweep);
  reply.x = num2cell(x');
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
