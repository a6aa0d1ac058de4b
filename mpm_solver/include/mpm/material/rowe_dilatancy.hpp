#pragma once

#include <algorithm>
#include <cmath>

namespace mpm {

// Rowe's stress dilatancy, Tran et al., MPMICE, eq. 100:
//   sin psi_m = (sin phi_m - sin phi_r) / (1 - sin phi_r sin phi_m),
// clamped at psi_m >= 0 (no contraction beyond the residual state) [rad].
inline double rowe_dilation_angle(double mobilised_friction_angle, double residual_friction_angle) {
  const double sin_m = std::sin(mobilised_friction_angle);
  const double sin_r = std::sin(residual_friction_angle);
  return std::asin(std::max(0.0, (sin_m - sin_r) / (1.0 - sin_r * sin_m)));
}

}  // namespace mpm
