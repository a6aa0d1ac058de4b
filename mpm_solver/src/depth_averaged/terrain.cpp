#include "mpm/depth_averaged/terrain.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mpm {

Terrain::Terrain(double inclination, double gravity, std::optional<RasterGrid> bed)
    : inclination_(inclination),
      gravity_(gravity),
      normal_gravity_(gravity * std::cos(inclination)),
      bed_(std::move(bed)) {
  if (!(std::abs(inclination) < 0.5 * std::numbers::pi))
    throw std::invalid_argument("the reference plane's inclination must be below 90 degrees");
  if (!(gravity >= 0.0) || !std::isfinite(gravity))
    throw std::invalid_argument("gravity must be finite and not negative");
}

double Terrain::height_of_level(double elevation, const Vec<2>& x) const {
  return (elevation + x[0] * std::sin(inclination_)) / std::cos(inclination_);
}

Vec<2> Terrain::driving_acceleration(const Vec<2>& x) const {
  Vec<2> a = -normal_gravity_ * bed_slope(x);
  a[0] += gravity_ * std::sin(inclination_);
  return a;
}

}  // namespace mpm
