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
  if (!(structured_share >= 0.0 && structured_share <= 1.0))
    fail("structured share must be in [0, 1]", structured_share);
  if (!(basal_pressure_factor >= 0.0 && basal_pressure_factor <= 1.0))
    fail("basal pressure factor must be in [0, 1]", basal_pressure_factor);
  if (!(in_plane.youngs_modulus >= 0.0) || !std::isfinite(in_plane.youngs_modulus))
    fail("Young's modulus must not be negative", in_plane.youngs_modulus);
  if (!(in_plane.poisson_ratio >= 0.0 && in_plane.poisson_ratio < 0.5))
    fail("Poisson's ratio must be in [0, 0.5)", in_plane.poisson_ratio);
  if (!(confined_fluid_fraction >= 0.0 && confined_fluid_fraction < 1.0))
    fail("confined fluid fraction must be in [0, 1)", confined_fluid_fraction);
  if (!(fragmentation_strain >= 0.0) || !std::isfinite(fragmentation_strain))
    fail("fragmentation strain must not be negative", fragmentation_strain);
}

// Eq. 28 over a step in which the column dilates by d eps_v, with
// c = c0 (1 - D): d ln f_sc = -max(0, d eps_v) / ((1 - D) eps_f).
double DepthAveragedMaterial::structured_share_after(double share, double damage,
                                                     double volumetric_strain) const {
  const double eps_f =
      fragmentation_strain > 0.0 ? fragmentation_strain : degradation.critical_volumetric_strain();
  if (!(eps_f > 0.0) || damage >= 1.0 || volumetric_strain <= 0.0) return share;
  return share * std::exp(-volumetric_strain / ((1.0 - damage) * eps_f));
}

}  // namespace mpm
