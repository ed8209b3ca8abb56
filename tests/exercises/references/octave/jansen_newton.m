% A correct student solution of `numlab exercise` jansen-newton in Octave (7 or later): full
% Newton-Raphson on seed 000's 8-equation Jansen closure (from the task's equations), with its trace.
1;

function reply = solve(request)
  crank = request.crank_angle;
  [theta, status, iterations, trace] = newton(@(t) closure(crank, t), request.theta0(:), request.tolerance, ...
                                              request.max_iterations);
  reply = struct('status', status, 'iterations', iterations);
  reply.theta = num2cell(theta');
  reply.trace = num2cell(trace);  % a cell: a list even with one entry
end

% f and J at crank angle `crank` and angles theta1 ... theta8 (a column).
function [f, J] = closure(crank, theta)
  LI = 15; A_OFFSET = 7.8; B_OFFSET = 38;
  [LI, A_OFFSET, B_OFFSET, LENGTHS] = variant_lengths(LI, A_OFFSET, B_OFFSET, [50, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7]);
  % Each y row (1, 3, 5, 7) as [angle index, sign] terms; the x row below it has the same terms.
  ROWS = {[1, 1; 2, -1], [1, 1; 3, 1; 4, -1], [6, 1; 7, -1], [1, 1; 3, 1; 5, 1; 7, -1; 8, -1]};
  s = sin(theta);
  c = cos(theta);
  Y = LI * sin(crank) + A_OFFSET;
  X = LI * cos(crank) + B_OFFSET;
  f = zeros(8, 1);
  J = zeros(8, 8);
  for pair = 1:4
    terms = ROWS{pair};
    k = terms(:, 1);
    signs = terms(:, 2);
    y_row = 2 * pair - 1;
    f(y_row) = Y + sum(signs .* LENGTHS(k)' .* s(k));
    f(y_row + 1) = X + sum(signs .* LENGTHS(k)' .* c(k));
    J(y_row, k) = signs .* LENGTHS(k)' .* c(k);
    J(y_row + 1, k) = -signs .* LENGTHS(k)' .* s(k);
  end
end

% Full Newton-Raphson: stop when max |f_i| <= tolerance; else J dx = -f (LU with partial
% pivoting), x <- x + dx.
function [x, status, iterations, trace] = newton(evaluate, x, tolerance, max_iterations)
  trace = struct('residual_inf', {}, 'step_inf', {});
  [f, J] = evaluate(x);
  status = 'max_iterations';
  iterations = 0;
  while true
    if max(abs(f)) <= tolerance
      status = 'converged';
      break;
    end
    if iterations >= max_iterations
      break;
    end
    [L, U, P] = lu(J);
    if any(diag(U) == 0)
      status = 'singular';
      break;
    end
    dx = U \ (L \ (P * -f));
    x = x + dx;
    iterations += 1;
    [f, J] = evaluate(x);
    trace(end + 1) = struct('residual_inf', max(abs(f)), 'step_inf', max(abs(dx)));
    if ~all(isfinite(f))
      status = 'diverged';
      break;
    end
  end
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

% Seed 000's lengths, or the variant's when the request carries them (TASK.md, "Your variant"):
% lengths are l1 ... l8.
function [li, a, b, lengths] = variant_lengths(li, a, b, lengths)
  global REQUEST_LENGTHS
  if ~isempty(REQUEST_LENGTHS)
    g = REQUEST_LENGTHS;
    li = g.crank;
    a = g.a;
    b = g.b;
    lengths = [g.l1, g.l2, g.l3, g.l4, g.l5, g.l6, g.l7, g.l8];
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
  global REQUEST_LENGTHS
  REQUEST_LENGTHS = [];
  if isfield(request, 'lengths')
    REQUEST_LENGTHS = request.lengths;
  end
  try
    reply = solve(request);
  catch err  % the checker reports it as this check's failure
    reply = struct('error', err.message);
  end
  reply.id = request.id;
  fputs(stdout, [to_json(reply), "\n"]);
  fflush(stdout);
end
