#pragma once

#include <array>
#include <span>
#include <vector>

#include "cosim/mesh.hpp"

namespace swe {

// Where an initial value applies; later regions override earlier ones.
struct InitialRegion {
  enum class Shape { everywhere, box, circle };
  Shape shape = Shape::everywhere;
  std::array<double, 2> min{0.0, 0.0}, max{0.0, 0.0};  // box
  std::array<double, 2> centre{0.0, 0.0};              // circle
  double radius = 0.0;
  bool free_surface = true;  // level is a free-surface elevation eta; else a depth
  double level = 0.0;        // [m]
  std::array<double, 2> velocity{0.0, 0.0};

  bool contains(const cosim::Vec3& x, int dimension) const;
};

// The initial water of a case, given relative to the bed so that it can be
// laid again over a bed received from a coupled solver: a free surface eta
// gives h = max(0, eta - B) and a depth d gives h = d.
struct InitialCondition {
  std::vector<InitialRegion> regions;  // the first applies everywhere

  // Depth and discharges per cell of `cells` over `bed` (hv is empty in 1D).
  void lay(const cosim::Mesh& cells, std::span<const double> bed, std::vector<double>& h,
           std::vector<double>& hu, std::vector<double>& hv) const;
};

}  // namespace swe
