% BUG: det = b*c - a*d (the product order reversed), so the whole inverse has the wrong sign
% CAUSE: determinant_sign
function reply = solve(request)
  M = request.A;
  reply = struct();
  big = max(abs(M(:)));
  if big == 0
    reply.status = 'singular';
    return;
  end
  [~, e] = log2(big);
  M = pow2(M, -e);
  a = M(1, 1); b = M(1, 2); c = M(2, 1); d = M(2, 2);
  dt = b * c - a * d;
  if abs(dt) <= eps * sum(M(:) .^ 2)
    reply.status = 'singular';
    return;
  end
  reply.inverse = pow2([d, -b; -c, a] / dt, -e);
end
