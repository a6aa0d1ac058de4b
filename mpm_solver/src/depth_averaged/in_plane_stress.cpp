#include "mpm/depth_averaged/in_plane_stress.hpp"

#include <algorithm>
#include <cmath>

namespace mpm {

double InPlaneStress::wave_speed(double density) const {
  if (!enabled()) return 0.0;
  return std::sqrt(youngs_modulus / ((1.0 - poisson_ratio * poisson_ratio) * density));
}

Mat<2> InPlaneStress::elastic_update(const Mat<2>& stress, const Mat<2>& velocity_gradient,
                                     double dt) const {
  const Mat<2> D = 0.5 * (velocity_gradient + velocity_gradient.transpose());
  const Mat<2> W = 0.5 * (velocity_gradient - velocity_gradient.transpose());
  const double plane_modulus = youngs_modulus / (1.0 - poisson_ratio * poisson_ratio);
  const Mat<2> rate =
      W * stress - stress * W +
      plane_modulus * ((1.0 - poisson_ratio) * D + poisson_ratio * D.trace() * Mat<2>::Identity());
  return stress + dt * rate;
}

Mat<2> InPlaneStress::bounded(const Mat<2>& total, double cohesion, double friction_angle,
                              bool& yielded) {
  const double centre = 0.5 * total.trace();
  const Mat<2> deviator = total - centre * Mat<2>::Identity();
  const double radius = std::sqrt(0.25 * (total(0, 0) - total(1, 1)) * (total(0, 0) - total(1, 1)) +
                                  total(0, 1) * total(0, 1));
  const double sin_phi = std::sin(friction_angle), cos_phi = std::cos(friction_angle);
  yielded = false;
  if (sin_phi > 0.0) {
    const double apex = cohesion * cos_phi / sin_phi;
    if (centre >= apex) {
      yielded = true;
      return apex * Mat<2>::Identity();
    }
    const double allowed = cohesion * cos_phi - centre * sin_phi;
    if (radius <= allowed) return total;
    yielded = true;
    return centre * Mat<2>::Identity() + (allowed / radius) * deviator;
  }
  // Tresca with a tension cut-off at c.
  Mat<2> result = total;
  if (radius > cohesion) {
    yielded = true;
    result = centre * Mat<2>::Identity() + (cohesion / radius) * deviator;
  }
  const double largest = 0.5 * result.trace() + std::min(radius, cohesion);
  if (largest > cohesion) {
    yielded = true;
    result -= (largest - cohesion) * Mat<2>::Identity();
  }
  return result;
}

}  // namespace mpm
