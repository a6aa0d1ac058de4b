#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "swe/solver_2d.hpp"

namespace swe_2d_test {

inline swe::Boundaries2d all_sides(swe::BoundaryKind kind, double value = 0.0) {
  const swe::Boundary b{kind, value};
  return {b, b, b, b};
}

// Values f(x, y) at the cell centres, x fastest.
inline std::vector<double> sample(const swe::Grid2d& grid,
                                  const std::function<double(double, double)>& f) {
  std::vector<double> values;
  for (int j = 0; j < grid.cells[1]; ++j)
    for (int i = 0; i < grid.cells[0]; ++i)
      values.push_back(f(grid.origin[0] + (i + 0.5) * grid.spacing[0],
                         grid.origin[1] + (j + 0.5) * grid.spacing[1]));
  return values;
}

inline void run_steps(swe::Solver& solver, int steps) {
  for (int n = 0; n < steps; ++n) solver.step(solver.stable_time_step());
}

inline double max_speed(const swe::Solver& solver) {
  double speed = 0.0;
  const auto h = solver.depth();
  const auto hu = solver.discharge_x();
  const auto hv = solver.discharge_y();
  for (std::size_t c = 0; c < h.size(); ++c)
    if (h[c] >= solver.physics().dry_depth)
      speed = std::max({speed, std::abs(hu[c] / h[c]), std::abs(hv[c] / h[c])});
  return speed;
}

}  // namespace swe_2d_test
