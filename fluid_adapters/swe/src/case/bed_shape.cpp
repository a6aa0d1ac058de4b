#include "swe/case/bed_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swe {

double BedShape::at(double x, double y) const {
  double b = base;
  if (!profile.empty()) {
    if (x <= profile.front()[0]) {
      b += profile.front()[1];
    } else if (x >= profile.back()[0]) {
      b += profile.back()[1];
    } else {
      const auto upper =
          std::upper_bound(profile.begin(), profile.end(), x,
                           [](double v, const std::array<double, 2>& p) { return v < p[0]; });
      const auto& p1 = *upper;
      const auto& p0 = *(upper - 1);
      const double s = (x - p0[0]) / (p1[0] - p0[0]);
      b += p0[1] + s * (p1[1] - p0[1]);
    }
  }
  for (const BedBump& bump : bumps) {
    const double r = std::hypot(x - bump.centre[0], y - bump.centre[1]);
    if (r < bump.radius) {
      const double c = std::cos(0.5 * std::numbers::pi * r / bump.radius);
      b += bump.height * c * c;
    }
  }
  return b;
}

}  // namespace swe
