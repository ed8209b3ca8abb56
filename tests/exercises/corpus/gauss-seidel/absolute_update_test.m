% BUG: the stop test is norm(x - xold, inf) <= tol, an absolute test without the max(1, max|x_i|) factor
% CAUSE: stop_test
% SET: heldout
function reply = solve(request)
  A = request.A;
  b = request.b(:);
  if request.normal_equations
    b = A' * b;
    A = A' * A;
  end
  x = request.x0(:);
  n = numel(x);
  tol = request.tolerance;
  sweeps = {};
  reply = struct('status', 'max_iterations');
  u1 = 0;
  for it = 1:request.max_iterations
    xold = x;
    for i = 1:n
      s = A(i, :) * x - A(i, i) * x(i);
      x(i) = (b(i) - s) / A(i, i);
    end
    u = norm(x - xold, inf);
    if it == 1
      u1 = u;
    end
    sweeps{end + 1} = struct('x', x', 'update_inf', u);
    if u <= tol
      reply.status = 'converged';
      break;
    end
    if u > 1e8 * max(u1, tol)
      reply.status = 'diverged';
      break;
    end
  end
  reply.x = x';
  reply.iterations = it;
  reply.trace = sweeps;
end
