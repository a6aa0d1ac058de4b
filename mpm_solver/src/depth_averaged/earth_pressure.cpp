#include "mpm/depth_averaged/earth_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mpm {

EarthPressureModel earth_pressure_model_from(const std::string& name) {
  if (name == "isotropic") return EarthPressureModel::isotropic;
  if (name == "rankine") return EarthPressureModel::rankine;
  throw std::invalid_argument("unknown earth pressure model '" + name + "' (isotropic or rankine)");
}

std::string to_string(EarthPressureModel model) {
  return model == EarthPressureModel::isotropic ? "isotropic" : "rankine";
}

double EarthPressure::coefficient(double internal_friction_angle, double areal_strain_rate) const {
  if (model_ == EarthPressureModel::isotropic) return 1.0;
  const double s = std::sin(internal_friction_angle);
  const double active = (1.0 - s) / (1.0 + s);  // eq. 42
  return areal_strain_rate >= 0.0 ? active : 1.0 / active;
}

double EarthPressure::crack_depth(double K, double unit_weight, double cohesion) {
  if (cohesion <= 0.0) return 0.0;
  return 2.0 * cohesion / (unit_weight * std::sqrt(K));
}

double EarthPressure::thrust(double K, double unit_weight, double cohesion, double depth) {
  const double loaded = std::max(0.0, depth - crack_depth(K, unit_weight, cohesion));
  return 0.5 * K * unit_weight * loaded * loaded;
}

}  // namespace mpm
