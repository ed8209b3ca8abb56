// BUG: the y rows of J use d(l sin t)/dt = -l cos t (a minus sign where there is none)
// CAUSE: derivative_sign
#include <array>

namespace {
const std::array<double, 10> len = {50.0, 41.5, 55.8, 40.1, 39.4, 39.3, 36.7, 61.9, 49.0, 65.7};
// coefficient of each unknown's vector in each loop; loops 0 and 3 start with P1->A
const std::array<std::array<int, 10>, 5> coef = {{{1, 1, 0, 0, 0, 0, 0, 0, 0, 0},
                                                  {0, -1, 1, 1, 0, 0, 0, 0, 0, 0},
                                                  {0, 0, 0, 1, -1, 1, -1, 0, 0, 0},
                                                  {0, 0, 0, 0, 0, -1, 0, -1, 0, 0},
                                                  {0, 0, 0, 0, 0, 0, 1, 0, 1, 1}}};
}  // namespace

json solve(const json& request) {
  const Vector th = numlab::exercise::vector(request["theta"]);
  const double t2 = request["crank_angle"].get<double>();
  const double X = 38.0 + 15.0 * std::cos(t2), Y = 7.8 + 15.0 * std::sin(t2);
  Vector f(10, 0.0);
  Matrix J(10, Vector(10, 0.0));
  for (int loop = 0; loop < 5; ++loop) {
    const bool crank = loop == 0 || loop == 3;
    f[2 * loop] = crank ? X : 0.0;
    f[2 * loop + 1] = crank ? Y : 0.0;
    for (int k = 0; k < 10; ++k) {
      const double w = coef[loop][k] * len[k];
      f[2 * loop] += w * std::cos(th[k]);
      f[2 * loop + 1] += w * std::sin(th[k]);
      J[2 * loop][k] = -w * std::sin(th[k]);
      J[2 * loop + 1][k] = -w * std::cos(th[k]);
    }
  }
  return json{{"f", f}, {"J", J}};
}
