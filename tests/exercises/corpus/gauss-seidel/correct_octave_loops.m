% BUG: none: Gauss-Seidel with row slices (the part left of the diagonal from this sweep, the part right of it from the last), M = A'A and c = A'b for the normal equations, the exact stop rule and the trace (a check against false failures)
% CAUSE: none
% SET: heldout
function reply = solve(request)
  M = request.A;
  c = request.b(:);
  if request.normal_equations
    c = M' * c;
    M = M' * M;
  end
  x = request.x0(:);
  n = numel(x);
  history = cell(1, 0);
  reply = struct('status', 'max_iterations');
  for sweep = 1:request.max_iterations
    before = x;
    for i = 1:n
      left = M(i, 1:i-1) * x(1:i-1);
      right = M(i, i+1:n) * x(i+1:n);
      x(i) = (c(i) - left - right) / M(i, i);
    end
    change = norm(x - before, Inf);
    if sweep == 1
      u1 = change;
    end
    history{sweep} = struct('x', x', 'update_inf', change);
    if change <= request.tolerance * max([1; abs(x)])
      reply.status = 'converged';
      break;
    elseif change > 1e8 * max(u1, request.tolerance)
      reply.status = 'diverged';
      break;
    end
  end
  reply.iterations = sweep;
  reply.x = x';
  reply.trace = history;
end
