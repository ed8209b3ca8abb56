% BUG: J is built with the gradient of each f_i as its column i (J(k, i) = d f_i / d v_k) and the step solves J \ -f with it: the whole Jacobian transposed
% CAUSE: transposed_jacobian
% SET: heldout
function f = loops(th, v)
  b = pi / 9; r = sqrt(0.5); q = 4 / 3; ch = 5 * cos(b);
  A = v(1); B = v(2); C = v(3); D = v(4); E = v(5); F = v(6); G = v(7); H = v(8);
  f = [-2.5 * cos(th) + 2 * cos(A) + 2 * cos(B);
       -1 - 2.5 * sin(th) + 2 * sin(A) + 2 * sin(B);
       -r + ch * cos(th + b) + q * cos(C) - 5 * cos(D);
       1 + r + ch * sin(th + b) - q * sin(C) - 5 * sin(D);
       q * cos(th + b) + 4 * cos(C - b) - 4.5 * cos(E) - q * cos(F);
       q * sin(th + b) - 4 * sin(C - b) + 4.5 * sin(E) - q * sin(F);
       cos(C + b) + q * cos(F) - q * cos(G) + cos(H);
       -sin(C + b) + q * sin(F) + q * sin(G) - sin(H)];
end

% column i: the gradient of f_i with respect to A ... H
function J = gradients(v)
  b = pi / 9; q = 4 / 3;
  A = v(1); B = v(2); C = v(3); D = v(4); E = v(5); F = v(6); G = v(7); H = v(8);
  J = zeros(8);
  J([1 2], 1) = [-2 * sin(A); -2 * sin(B)];
  J([1 2], 2) = [2 * cos(A); 2 * cos(B)];
  J([3 4], 3) = [-q * sin(C); 5 * sin(D)];
  J([3 4], 4) = [-q * cos(C); -5 * cos(D)];
  J([3 5 6], 5) = [-4 * sin(C - b); 4.5 * sin(E); q * sin(F)];
  J([3 5 6], 6) = [-4 * cos(C - b); 4.5 * cos(E); -q * cos(F)];
  J([3 6 7 8], 7) = [-sin(C + b); -q * sin(F); q * sin(G); -sin(H)];
  J([3 6 7 8], 8) = [-cos(C + b); q * cos(F); q * cos(G); -cos(H)];
end

function reply = solve(request)
  th = request.crank_angle;
  v = request.guess(:);
  f = loops(th, v);
  steps = {};
  n = 0;
  status = 'max_iterations';
  while true
    if max(abs(f)) <= request.tolerance
      status = 'converged';
      break;
    end
    if n >= request.max_iterations
      break;
    end
    dv = gradients(v) \ -f;
    v = v + dv;
    n = n + 1;
    f = loops(th, v);
    steps{end + 1} = struct('residual_inf', max(abs(f)), 'step_inf', max(abs(dv)));
  end
  reply = struct('status', status, 'iterations', n);
  reply.angles = v';
  reply.trace = steps;
end
