% BUG: sind and cosd (degree functions) are used on angles given in radians
% CAUSE: degrees_for_radians
function reply = solve(request)
  L = [50, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7];
  t = request.theta(:)';
  ti = request.crank_angle;
  Y = 15 * sind(ti) + 7.8;
  X = 15 * cosd(ti) + 38;
  S = L .* sind(t);
  C = L .* cosd(t);
  dS = L .* cosd(t);
  dC = -L .* sind(t);
  rows = {[1 -1 0 0 0 0 0 0], [1 0 1 -1 0 0 0 0], [0 0 0 0 0 1 -1 0], [1 0 1 0 1 0 -1 -1]};
  f = zeros(8, 1);
  J = zeros(8, 8);
  for r = 1:4
    w = rows{r};
    f(2*r - 1) = Y + sum(w .* S);
    f(2*r) = X + sum(w .* C);
    J(2*r - 1, :) = w .* dS;
    J(2*r, :) = w .* dC;
  end
  reply = struct('f', f, 'J', J);
end
