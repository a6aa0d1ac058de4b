#include "mpm/depth_averaged/depth_averaged_material.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mpm {

void DepthAveragedMaterial::check() const {
  const auto fail = [&](const char* what, double value) {
    throw std::invalid_argument(fmt::format("material '{}': {} = {}", name, what, value));
  };
  if (!(density > 0.0) || !std::isfinite(density)) fail("density must be positive", density);
  for (const auto& [what, angle] : {std::pair{"internal friction angle", internal_friction_angle},
                                    std::pair{"basal friction angle", basal_friction_angle}})
    if (!(angle >= 0.0 && angle < 0.5 * std::numbers::pi))
      fail(fmt::format("{} must be in [0, 90) degrees; it is in rad", what).c_str(), angle);
  if (!(cohesion >= 0.0) || !std::isfinite(cohesion))
    fail("cohesion must not be negative", cohesion);
}

}  // namespace mpm
