#pragma once

#include <array>
#include <vector>

namespace swe {

// A bump of the bed: height * cos^2(pi r / (2 radius)) within `radius` of
// `centre` (r measured in x only in 1D), zero beyond.
struct BedBump {
  std::array<double, 2> centre{0.0, 0.0};
  double radius = 1.0;
  double height = 0.0;
};

// The initial bed B(x, y) of a case [m]: a base elevation plus a piecewise
// linear profile along x (constant beyond its ends) plus bumps.
struct BedShape {
  double base = 0.0;
  std::vector<std::array<double, 2>> profile;  // (x, B) with increasing x
  std::vector<BedBump> bumps;

  double at(double x, double y = 0.0) const;
};

}  // namespace swe
