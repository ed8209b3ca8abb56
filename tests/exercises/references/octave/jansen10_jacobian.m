% A correct student solution of `numlab exercise` jansen10-jacobian in Octave (7 or later): seed
% 001's 10-equation Jansen closure f and its analytic Jacobian J, from the task's equations.
1;

function reply = solve(request)
  [f, J] = closure(request.crank_angle, request.theta(:));
  reply = struct('f', {num2cell(f')}, 'J', J);
end

% f and J at crank angle theta2 = `crank` and angles theta3 ... theta12 (a column).
function [f, J] = closure(crank, theta)
  LI = 15; A_OFFSET = 7.8; B_OFFSET = 38;
  % |r3| ... |r12|: the lengths of the links whose directions are theta3 ... theta12.
  [LI, A_OFFSET, B_OFFSET, LENGTHS] = variant_lengths(LI, A_OFFSET, B_OFFSET, [50, 41.5, 55.8, 40.1, 39.4, 39.3, 36.7, 61.9, 49, 65.7]);
  % Each loop: whether it starts with P1->A, and its [angle index, sign] terms (index 1 is theta3).
  % Row 2 loop - 1 is the loop's x component (cosines), row 2 loop its y component (sines).
  FROM_CRANK = [true, false, false, true, false];
  LOOPS = {[1, 1; 2, 1], [2, -1; 3, 1; 4, 1], [4, 1; 5, -1; 6, 1; 7, -1], [6, -1; 8, -1], [7, 1; 9, 1; 10, 1]};
  s = sin(theta);
  c = cos(theta);
  X = B_OFFSET + LI * cos(crank);
  Y = A_OFFSET + LI * sin(crank);
  f = zeros(10, 1);
  J = zeros(10, 10);
  for loop = 1:5
    k = LOOPS{loop}(:, 1);
    signs = LOOPS{loop}(:, 2);
    x_row = 2 * loop - 1;
    y_row = 2 * loop;
    f(x_row) = FROM_CRANK(loop) * X + sum(signs .* LENGTHS(k)' .* c(k));
    f(y_row) = FROM_CRANK(loop) * Y + sum(signs .* LENGTHS(k)' .* s(k));
    J(x_row, k) = -signs .* LENGTHS(k)' .* s(k);
    J(y_row, k) = signs .* LENGTHS(k)' .* c(k);
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
% lengths are |r3| ... |r12| (l1 ... l5, l7, l8, l6, l9, l10).
function [li, a, b, lengths] = variant_lengths(li, a, b, lengths)
  global REQUEST_LENGTHS
  if ~isempty(REQUEST_LENGTHS)
    g = REQUEST_LENGTHS;
    li = g.crank;
    a = g.a;
    b = g.b;
    lengths = [g.l1, g.l2, g.l3, g.l4, g.l5, g.l7, g.l8, g.l6, g.l9, g.l10];
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
