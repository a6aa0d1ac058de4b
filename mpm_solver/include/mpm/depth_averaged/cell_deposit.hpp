#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "cosim/mesh.hpp"
#include "mpm/core/tensor.hpp"
#include "mpm/shape/grid_geometry.hpp"

namespace mpm {

// The cells of a ground grid as a cell-centred 2D mesh.
cosim::UniformGrid ground_cells(const GridGeometry<2>& grid);

// Points' amounts onto the cells of a cell-centred 2D grid and back, exactly
// conserved both ways. A point shares itself among the four cell centres
// around it with bilinear (cloud-in-cell) weights, clamped per direction at
// the grid's edges, so its shares are non-negative and sum to one.
class CellDeposit {
 public:
  // Throws std::invalid_argument for a grid that is not 2D, cell-centred and
  // at least 2 x 2 cells.
  explicit CellDeposit(cosim::UniformGrid cells);

  const cosim::UniformGrid& cells() const { return cells_; }

  // f(cell, share) for the point at x.
  template <class F>
  void for_each_share(const Vec<2>& x, F&& f) const {
    std::size_t lower[2];
    double upper_share[2];
    for (int d = 0; d < 2; ++d) {
      const auto n = cells_.cells[static_cast<std::size_t>(d)];
      const double xi = (x[d] - cells_.origin[static_cast<std::size_t>(d)]) /
                            cells_.spacing[static_cast<std::size_t>(d)] -
                        0.5;
      const double i0 = std::floor(xi);
      if (!(i0 >= 0.0)) {  // below the first centre (or NaN)
        lower[d] = 0;
        upper_share[d] = 0.0;
      } else if (i0 >= static_cast<double>(n - 1)) {
        lower[d] = static_cast<std::size_t>(n - 2);
        upper_share[d] = 1.0;
      } else {
        lower[d] = static_cast<std::size_t>(i0);
        upper_share[d] = xi - i0;
      }
    }
    const auto nx = static_cast<std::size_t>(cells_.cells[0]);
    for (std::size_t b = 0; b < 2; ++b)
      for (std::size_t a = 0; a < 2; ++a) {
        const double share = (a ? upper_share[0] : 1.0 - upper_share[0]) *
                             (b ? upper_share[1] : 1.0 - upper_share[1]);
        f((lower[1] + b) * nx + lower[0] + a, share);
      }
  }

  // Per cell, the sum of the points' values times their shares;
  // `components` values per point and per cell (side by side).
  std::vector<double> deposit(std::span<const Vec<2>> positions, std::span<const double> values,
                              std::size_t components) const;

  // The reverse: each cell's amount (`components` per cell) to the points in
  // proportion to share x weight (weights >= 0, e.g. the points' masses).
  // The amount of a cell no point weighs in goes first to the nearest cells
  // that have weight (square rings of cells around it, in proportion to their
  // weight), so the points receive the cells' whole amount to round-off
  // unless no point has weight at all; `unplaced` then gets the total per
  // component (it may be null). Returns `components` values per point.
  std::vector<double> distribute(std::span<const Vec<2>> positions, std::span<const double> weights,
                                 std::span<const double> amounts, std::size_t components,
                                 std::vector<double>* unplaced) const;

 private:
  cosim::UniformGrid cells_;
};

}  // namespace mpm
