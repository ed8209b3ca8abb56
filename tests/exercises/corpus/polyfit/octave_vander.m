% BUG: Octave's vander(x, D + 1) puts the highest power first, so the coefficients come out highest power first
% CAUSE: powers_reversed
function reply = solve(request)
  x = request.x(:);
  y = request.y(:);
  D = request.degree;
  reply = struct();
  if numel(unique(x)) < D + 1
    reply.status = 'singular';
    return;
  end
  V = vander(x, D + 1);
  s = sqrt(sum(V .^ 2, 1));
  [Q, R] = qr(V ./ s, 0);
  coef = (R \ (Q' * y)) ./ s';
  reply.coefficients = num2cell(coef');
end
