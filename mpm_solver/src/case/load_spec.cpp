#include <algorithm>
#include <cmath>
#include <numbers>

#include "mpm/case/case_description.hpp"

namespace mpm {

double LoadSpec::ramp_factor(double time) const {
  if (!(ramp_time > 0.0)) return 1.0;
  const double s = std::clamp(time / ramp_time, 0.0, 1.0);
  if (ramp_shape == RampShape::linear) return s;
  return s - std::sin(2.0 * std::numbers::pi * s) / (2.0 * std::numbers::pi);
}

}  // namespace mpm
