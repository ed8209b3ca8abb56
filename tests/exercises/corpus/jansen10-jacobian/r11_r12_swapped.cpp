// BUG: the lengths of r11 (D->F, 49) and r12 (F->E, 65.7) are exchanged in the student's table, so loop 5 of f and J uses 65.7 for theta11 and 49 for theta12
// CAUSE: wrong_link
// SET: heldout
namespace {
// |r3| ... |r12|, index k - 3
const double R[10] = {50.0, 41.5, 55.8, 40.1, 39.4, 39.3, 36.7, 61.9, 65.7, 49.0};
// each row pair: the crank term's weight (1 or 0) and the sign of every vector
struct Loop {
  double crank;
  int sign[10];
};
const Loop LOOPS[5] = {{1, {1, 1, 0, 0, 0, 0, 0, 0, 0, 0}},
                       {0, {0, -1, 1, 1, 0, 0, 0, 0, 0, 0}},
                       {0, {0, 0, 0, 1, -1, 1, -1, 0, 0, 0}},
                       {1, {0, 0, 0, 0, 0, -1, 0, -1, 0, 0}},
                       {0, {0, 0, 0, 0, 0, 0, 1, 0, 1, 1}}};
}  // namespace

json solve(const json& request) {
  const double crank = request["crank_angle"].get<double>();
  const Vector theta = numlab::exercise::vector(request["theta"]);
  if (theta.size() != 10) throw std::runtime_error("theta needs 10 angles");
  const double X = 38.0 + 15.0 * std::cos(crank);
  const double Y = 7.8 + 15.0 * std::sin(crank);
  Vector f(10, 0.0);
  Matrix J(10, Vector(10, 0.0));
  for (int p = 0; p < 5; ++p) {
    f[2 * p] = LOOPS[p].crank * X;
    f[2 * p + 1] = LOOPS[p].crank * Y;
    for (int k = 0; k < 10; ++k) {
      const double w = LOOPS[p].sign[k] * R[k];
      f[2 * p] += w * std::cos(theta[k]);
      f[2 * p + 1] += w * std::sin(theta[k]);
      J[2 * p][k] = -w * std::sin(theta[k]);
      J[2 * p + 1][k] = w * std::cos(theta[k]);
    }
  }
  return json{{"f", f}, {"J", J}};
}
