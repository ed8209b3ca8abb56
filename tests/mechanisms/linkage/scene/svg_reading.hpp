#pragma once
// Reading a linkage scene's SVG text back in the scene tests: where a joint's circle is drawn.

#include <catch2/catch.hpp>
#include <Eigen/Core>
#include <regex>
#include <string>

// The centre of joint `name`'s circle (id="joint-NAME"), in SVG coordinates.
inline Eigen::Vector2d circle_of(const std::string& svg, const std::string& name) {
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("id=\"joint-" + name + "\" cx=\"([-0-9.]+)\" cy=\"([-0-9.]+)\"")));
  return {std::stod(m[1]), std::stod(m[2])};
}
