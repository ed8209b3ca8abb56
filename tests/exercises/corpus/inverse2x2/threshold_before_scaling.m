% BUG: the singular test abs(det) < 1e-14 is made on A as given, before the scaling by a power of two (an absolute threshold: A = 1e-170 [4 7; 2 6] is called singular)
% CAUSE: absolute_singular_threshold
% SET: heldout
function reply = solve(request)
  A = request.A;
  if abs(A(1,1) * A(2,2) - A(1,2) * A(2,1)) < 1e-14
    reply = struct('status', 'singular');
    return;
  end
  [~, e] = log2(max(abs(A(:))));
  S = pow2(A, -e);
  dt = S(1,1) * S(2,2) - S(1,2) * S(2,1);
  B = [S(2,2), -S(1,2); -S(2,1), S(1,1)] / dt;
  reply = struct();
  reply.inverse = pow2(B, -e);
end
