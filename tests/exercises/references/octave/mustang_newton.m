% A correct student solution of `numlab exercise` mustang-newton in Octave (7 or later): full
% Newton-Raphson on seed 003's Mustang roof linkage (angles A ... H), from the task's equations,
% with its trace.
1;

function reply = solve(request)
  theta = request.crank_angle;
  L = seed_lengths();
  if isfield(request, 'lengths')  % a variant's lengths, by the same names
    L = request.lengths;
  end
  [angles, status, iterations, trace] = newton(@(v) closure(theta, v, L), request.guess(:), request.tolerance, ...
                                               request.max_iterations);
  reply = struct('status', status, 'iterations', iterations);
  reply.angles = num2cell(angles');
  reply.trace = num2cell(trace);  % a cell: a list even with one entry
end

% Seed 003's lengths |a b| as l_a_b.
function L = seed_lengths()
  L = struct('l1_3', 2, 'l3_4', 2, 'l2_4', 2.5, 'l0_5', 5, 'l5_6', 4 / 3, 'l6_7', 4 / 3, 'l6_8', 4, ...
             'l8_9', 1, 'l7_10', 4.5, 'l10_8', 4 / 3, 'l10_11', 4 / 3, 'l9_11', 1);
end

% f and J at crank angle theta and angles v = [A; B; C; D; E; F; G; H], with the lengths L.
function [f, J] = closure(theta, v, L)
  BEND = pi / 9;
  R = sqrt(0.5);
  CHORD = 2 * L.l2_4 * cos(BEND);  % |2 6|, the seed's 4.698
  A = v(1); B = v(2); C = v(3); D = v(4); E = v(5); F = v(6); G = v(7); H = v(8);
  f = [-L.l2_4 * cos(theta) + L.l1_3 * cos(A) + L.l3_4 * cos(B);
       -1 - L.l2_4 * sin(theta) + L.l1_3 * sin(A) + L.l3_4 * sin(B);
       -R + CHORD * cos(theta + BEND) + L.l5_6 * cos(C) - L.l0_5 * cos(D);
       1 + R + CHORD * sin(theta + BEND) - L.l5_6 * sin(C) - L.l0_5 * sin(D);
       L.l6_7 * cos(theta + BEND) + L.l6_8 * cos(C - BEND) - L.l7_10 * cos(E) - L.l10_8 * cos(F);
       L.l6_7 * sin(theta + BEND) - L.l6_8 * sin(C - BEND) + L.l7_10 * sin(E) - L.l10_8 * sin(F);
       L.l8_9 * cos(C + BEND) + L.l10_8 * cos(F) - L.l10_11 * cos(G) + L.l9_11 * cos(H);
       -L.l8_9 * sin(C + BEND) + L.l10_8 * sin(F) + L.l10_11 * sin(G) - L.l9_11 * sin(H)];
  J = zeros(8, 8);
  J(1, 1) = -L.l1_3 * sin(A);               J(1, 2) = -L.l3_4 * sin(B);
  J(2, 1) = L.l1_3 * cos(A);                J(2, 2) = L.l3_4 * cos(B);
  J(3, 3) = -L.l5_6 * sin(C);               J(3, 4) = L.l0_5 * sin(D);
  J(4, 3) = -L.l5_6 * cos(C);               J(4, 4) = -L.l0_5 * cos(D);
  J(5, 3) = -L.l6_8 * sin(C - BEND);        J(5, 5) = L.l7_10 * sin(E);   J(5, 6) = L.l10_8 * sin(F);
  J(6, 3) = -L.l6_8 * cos(C - BEND);        J(6, 5) = L.l7_10 * cos(E);   J(6, 6) = -L.l10_8 * cos(F);
  J(7, 3) = -L.l8_9 * sin(C + BEND);        J(7, 6) = -L.l10_8 * sin(F);  J(7, 7) = L.l10_11 * sin(G);  J(7, 8) = -L.l9_11 * sin(H);
  J(8, 3) = -L.l8_9 * cos(C + BEND);        J(8, 6) = L.l10_8 * cos(F);   J(8, 7) = L.l10_11 * cos(G);  J(8, 8) = -L.l9_11 * cos(H);
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
