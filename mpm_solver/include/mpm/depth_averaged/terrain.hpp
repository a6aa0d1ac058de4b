#pragma once

#include <optional>

#include "mpm/core/tensor.hpp"
#include "mpm/depth_averaged/raster_grid.hpp"

namespace mpm {

// The ground a depth-averaged mass moves over, in Savage & Hutter's frame: a
// reference plane inclined at theta, x pointing down its steepest slope and y
// across it, and the bed's elevation b(x, y) above that plane (a raster, or
// none). theta = 0 is the plan view of a catchment over its terrain raster.
// The bed's slopes are taken as small next to the plane (Gray et al. 1999's
// shallow topography): the normal gravity is g cos(theta) everywhere and the
// bed pushes with -g cos(theta) grad b.
class Terrain {
 public:
  explicit Terrain(double inclination = 0.0, double gravity = 9.81,
                   std::optional<RasterGrid> bed = std::nullopt);

  double inclination() const { return inclination_; }
  double gravity() const { return gravity_; }

  double bed_elevation(const Vec<2>& x) const { return bed_ ? bed_->value(x) : 0.0; }
  Vec<2> bed_slope(const Vec<2>& x) const { return bed_ ? bed_->gradient(x) : Vec<2>::Zero(); }

  // The height above the reference plane, along its normal, of the
  // horizontal level at world elevation z (the plane passing through
  // elevation 0 at x = 0): (z + x sin(theta)) / cos(theta) [m].
  double height_of_level(double elevation, const Vec<2>& x) const;

  // Gravity's component normal to the ground [m/s^2].
  double normal_gravity() const { return normal_gravity_; }
  // The acceleration gravity gives a mass along the ground at x [m/s^2]:
  // g sin(theta) down the plane and -g cos(theta) grad b
  // (van den Bout et al., OpenLISEM Hazard, eq. 54: g^x and the epsilon db/dx term).
  Vec<2> driving_acceleration(const Vec<2>& x) const;

 private:
  double inclination_;
  double gravity_;
  double normal_gravity_;
  std::optional<RasterGrid> bed_;
};

}  // namespace mpm
