#pragma once
// A four-bar O-A-B-Q as description text, for the tests of link angles and the crank analysis: crank
// a = |OA|, coupler b = |AB|, rocker c = |QB|, ground d = |OQ| along +x, every length times `scale`
// (a model in mm or km). The reference pose is the crank at `reference_deg` with B on the side
// `side` (+1 above the line A-Q, -1 below), placed by the textbook's circle intersection.

#include <cmath>
#include <fmt/format.h>
#include <string>

namespace numlab::mechanisms::testing {

inline std::string four_bar_text(double a, double b, double c, double d, double scale, double reference_deg = 60.0,
                                 int side = 1, const std::string& extra = "") {
  const double t = reference_deg * 3.141592653589793238462643383279502884 / 180.0;
  const double ax = a * std::cos(t), ay = a * std::sin(t);
  const double dx = d - ax, dy = -ay, e = std::hypot(dx, dy);
  const double along = (b * b - c * c + e * e) / (2.0 * e), h = std::sqrt(b * b - along * along);
  const double bx = ax + (along * dx - side * h * dy) / e, by = ay + (along * dy + side * h * dx) / e;
  return fmt::format(
      "[linkage]\nname = \"fb\"\n{}\n[ground]\nO = [0.0, 0.0]\nQ = [{:.17g}, 0.0]\n[joints]\nA = [{:.17g}, {:.17g}]\n"
      "B = [{:.17g}, {:.17g}]\n[[link]]\nname = \"crank\"\njoints = [\"O\", \"A\"]\nlength = {:.17g}\n[[link]]\n"
      "name = \"coupler\"\njoints = [\"A\", \"B\"]\nlength = {:.17g}\n[[link]]\nname = \"rocker\"\njoints = [\"Q\", \"B\"]\n"
      "length = {:.17g}\n[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = {:.17g}\n",
      extra, d * scale, ax * scale, ay * scale, bx * scale, by * scale, a * scale, b * scale, c * scale, reference_deg);
}

}  // namespace numlab::mechanisms::testing
