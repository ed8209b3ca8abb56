% BUG: the pivot row comes from max(a(k:n, k)) without abs: the largest signed entry, not the largest |a_ik|
% CAUSE: signed_pivot
function reply = solve(request)
  a = request.A;
  rhs = request.b(:);
  n = numel(rhs);
  small = n * eps * max(max(abs(a)));
  piv = {};
  reply = struct();
  for k = 1:n
    [~, m] = max(a(k:n, k));
    p = m + k - 1;
    a([k p], :) = a([p k], :);
    rhs([k p]) = rhs([p k]);
    if abs(a(k, k)) <= small
      reply.status = 'singular';
      return;
    end
    piv{end + 1} = struct('column', k - 1, 'pivot_row', p - 1, 'pivot', a(k, k));
    for i = k + 1:n
      f = a(i, k) / a(k, k);
      a(i, :) = a(i, :) - f * a(k, :);
      rhs(i) = rhs(i) - f * rhs(k);
    end
  end
  x = zeros(n, 1);
  for i = n:-1:1
    x(i) = (rhs(i) - a(i, i+1:n) * x(i+1:n)) / a(i, i);
  end
  reply.x = num2cell(x');
  reply.trace = piv;
end
