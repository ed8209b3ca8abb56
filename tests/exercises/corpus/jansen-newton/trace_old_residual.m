% BUG: the trace records norm(f, inf) of the residual before the step instead of after it
% CAUSE: trace_before_step
function [f, J] = leg(ti, t)
  L = [50, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7];
  W = [1 -1 0 0 0 0 0 0; 1 0 1 -1 0 0 0 0; 0 0 0 0 0 1 -1 0; 1 0 1 0 1 0 -1 -1];
  Y = 15 * sin(ti) + 7.8;
  X = 15 * cos(ti) + 38;
  f = zeros(8, 1);
  J = zeros(8, 8);
  for r = 1:4
    w = W(r, :) .* L;
    f(2*r - 1) = Y + w * sin(t);
    f(2*r) = X + w * cos(t);
    J(2*r - 1, :) = w .* cos(t');
    J(2*r, :) = -w .* sin(t');
  end
end

function reply = solve(request)
  t = request.theta0(:);
  tr = {};
  it = 0;
  status = 'max_iterations';
  while true
    [f, J] = leg(request.crank_angle, t);
    if norm(f, inf) <= request.tolerance
      status = 'converged';
      break;
    end
    if it >= request.max_iterations
      break;
    end
    dx = J \ (-f);
    t = t + dx;
    it = it + 1;
    tr{end + 1} = struct('residual_inf', norm(f, inf), 'step_inf', norm(dx, inf));
  end
  reply = struct('status', status, 'iterations', it);
  reply.theta = num2cell(t');
  reply.trace = tr;
end
