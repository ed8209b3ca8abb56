% BUG: with normal_equations the matrix swept is A*A' instead of A'*A (the right-hand side A'*b is right)
% CAUSE: a_at_instead_of_at_a
function reply = solve(request)
  A = request.A;
  b = request.b(:);
  if request.normal_equations
    M = A * A';
    c = A' * b;
  else
    M = A;
    c = b;
  end
  x = request.x0(:);
  n = numel(x);
  tr = {};
  status = 'max_iterations';
  u1 = 0;
  k = 0;
  while k < request.max_iterations
    k = k + 1;
    old = x;
    for i = 1:n
      s = c(i);
      for j = [1:i-1, i+1:n]
        s = s - M(i, j) * x(j);
      end
      x(i) = s / M(i, i);
    end
    u = max(abs(x - old));
    if k == 1
      u1 = u;
    end
    tr{end + 1} = struct('x', {num2cell(x')}, 'update_inf', u);
    if u <= request.tolerance * max(1, max(abs(x)))
      status = 'converged';
      break;
    end
    if u > 1e8 * max(u1, request.tolerance)
      status = 'diverged';
      break;
    end
  end
  reply = struct('status', status, 'iterations', k);
  reply.x = num2cell(x');
  reply.trace = tr;
end
