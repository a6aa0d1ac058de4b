#pragma once

#include <string>

namespace mpm {

// The lateral stress of a depth-averaged column, from its weight: sigma_xx =
// K sigma_zz, with K isotropic (1: the hydraulic limit of Mangeney et al.
// 2000's exact dam break) or Rankine's, active K_a where the column's plan
// area grows and passive K_p where it shrinks (van den Bout et al., OpenLISEM
// Hazard, eq. 42).
enum class EarthPressureModel { isotropic, rankine };

EarthPressureModel earth_pressure_model_from(const std::string& name);  // throws invalid_argument
std::string to_string(EarthPressureModel model);

class EarthPressure {
 public:
  explicit EarthPressure(EarthPressureModel model = EarthPressureModel::isotropic)
      : model_(model) {}

  EarthPressureModel model() const { return model_; }

  // K for a column of internal friction angle phi [rad] whose plan area
  // changes at the rate div(u) [1/s].
  double coefficient(double internal_friction_angle, double areal_strain_rate) const;

  // The depth [m] down to which a cohesive column stands in tension,
  // z_c = 2 c / (gamma sqrt(K)): Bell's lateral stress K sigma_zz - 2 c sqrt(K)
  // (eq. 43) is negative above it.
  static double crack_depth(double K, double unit_weight, double cohesion);

  // The lateral thrust [N/m], Bell's lateral stress integrated over the depth
  // h with the weight's sigma_zz = gamma (h - z), gamma = rho g cos(theta) [N/m^3],
  // and no tension (the cracks above z_c carry none):
  //   T = K gamma (h - z_c)^2 / 2 for h > z_c, else 0.
  // With c = 0 it is Savage & Hutter's K gamma h^2 / 2, whose depth average is
  // K times the mean vertical stress of eq. 41 (sigma_zz_bar = P_b / 2); eq. 43
  // as printed multiplies K with the basal value, which would double it.
  static double thrust(double K, double unit_weight, double cohesion, double depth);

 private:
  EarthPressureModel model_;
};

}  // namespace mpm
