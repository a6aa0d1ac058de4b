#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "cosim/mesh.hpp"
#include "mpm/core/tensor.hpp"
#include "mpm/grid/grid.hpp"

namespace mpm::coupling {

// The cell-centred (Dim-1)-D grid over the MPM grid's horizontal extent
// (mesh "mpm_surface"); the last MPM direction is vertical. Each surface
// cell is the top of a column of the MPM domain.
template <int Dim>
struct SurfaceGrid {
  static constexpr int horizontal = Dim - 1;
  std::array<double, horizontal> origin{};
  std::array<double, horizontal> spacing{};
  std::array<int, horizontal> cells{};
  double bottom = 0.0;  // elevation of the MPM grid's bottom face [m]

  static SurfaceGrid covering(const Grid<Dim>& grid, const std::array<int, horizontal>& cells) {
    SurfaceGrid s;
    for (std::size_t d = 0; d < horizontal; ++d) {
      const int k = static_cast<int>(d);
      s.origin[d] = grid.origin[k];
      s.spacing[d] = grid.spacing[k] * grid.cells[d] / cells[d];
      s.cells[d] = cells[d];
    }
    s.bottom = grid.origin[Dim - 1];
    return s;
  }

  std::size_t size() const {
    std::size_t n = 1;
    for (int c : cells) n *= static_cast<std::size_t>(c);
    return n;
  }
  // Horizontal area of a column [m^2] (its width [m] in 2D: per unit depth).
  double cell_area() const {
    double a = 1.0;
    for (double h : spacing) a *= h;
    return a;
  }
  // Index of the column along horizontal direction d holding coordinate x (clamped).
  int index_along(std::size_t d, double x) const {
    const double i = std::floor((x - origin[d]) / spacing[d]);
    return static_cast<int>(std::clamp(i, 0.0, static_cast<double>(cells[d] - 1)));
  }
  // The column holding a point's horizontal position (clamped), x fastest.
  std::size_t column_of(const Vec<Dim>& x) const {
    std::size_t f = 0, stride = 1;
    for (std::size_t d = 0; d < horizontal; ++d) {
      f += static_cast<std::size_t>(index_along(d, x[static_cast<int>(d)])) * stride;
      stride *= static_cast<std::size_t>(cells[d]);
    }
    return f;
  }

  cosim::UniformGrid mesh() const {
    cosim::UniformGrid m;
    m.dim = horizontal;
    for (std::size_t d = 0; d < horizontal; ++d) {
      m.origin[d] = origin[d];
      m.spacing[d] = spacing[d];
      m.cells[d] = cells[d];
    }
    m.location = cosim::GridLocation::cell;
    return m;
  }
};

}  // namespace mpm::coupling
