#pragma once

#include <array>

#include "mpm/core/tensor.hpp"

namespace mpm {

// Where the uniform background grid lies: the lower corner, the cell size
// per direction and the number of cells per direction. How many grid values
// it carries depends on the shape kernel (Kernel::dofs).
template <int Dim>
struct GridGeometry {
  Vec<Dim> origin = Vec<Dim>::Zero();
  Vec<Dim> spacing = Vec<Dim>::Ones();
  std::array<int, Dim> cells{};

  Vec<Dim> upper() const {
    Vec<Dim> u;
    for (int d = 0; d < Dim; ++d) u[d] = origin[d] + spacing[d] * cells[d];
    return u;
  }
  double cell_volume() const { return spacing.prod(); }
};

}  // namespace mpm
