// Lake at rest over a 2D bump whose top emerges as a dry island: surface
// 0.5 m, bump peak 0.8 m, walls. The hydrostatic reconstruction must keep the
// water still to round-off (well-balanced with dry cells).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "swe/solver_2d.hpp"

namespace {

TEST(Swe2dLakeAtRest, StaysAtRestAroundAnEmergedIsland) {
  const int n = 100, steps = 1000;
  const double surface = 0.5, tolerance = 1e-12;
  const swe::Grid2d grid{{0.0, 0.0}, {0.01, 0.01}, {n, n}};
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0};
  swe::Solver2d solver(grid, {}, {}, {wall, wall, wall, wall});
  std::vector<double> bed, depth;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * 0.01, y = (j + 0.5) * 0.01;
      const double b =
          0.8 * std::exp(-30.0 * ((x - 0.45) * (x - 0.45) + 0.6 * (y - 0.55) * (y - 0.55))) +
          0.1 * std::sin(7.0 * x) * std::sin(5.0 * y);
      bed.push_back(b);
      depth.push_back(std::max(0.0, surface - b));
    }
  }
  const auto dry = std::count(depth.begin(), depth.end(), 0.0);
  ASSERT_GT(dry, 100);
  solver.set_bed(bed);
  solver.set_state(depth, {}, {});
  for (int s = 0; s < steps; ++s) solver.step(solver.stable_time_step());

  double max_u = 0.0, max_v = 0.0, max_surface_change = 0.0;
  for (std::size_t c = 0; c < depth.size(); ++c) {
    const double h = solver.depth()[c];
    if (h >= solver.physics().dry_depth) {
      max_u = std::max(max_u, std::abs(solver.discharge_x()[c] / h));
      max_v = std::max(max_v, std::abs(solver.discharge_y()[c] / h));
    }
    max_surface_change = std::max(max_surface_change, std::abs(h - depth[c]));
  }
  fmt::print(
      "lake at rest, {} x {} cells ({} dry), {} steps: max |u| = {:.3e} m/s, max |v| = {:.3e} m/s "
      "(tolerance {:.0e}), max depth change {:.3e} m\n",
      n, n, dry, steps, max_u, max_v, tolerance, max_surface_change);
  EXPECT_LE(max_u, tolerance);
  EXPECT_LE(max_v, tolerance);
  EXPECT_LE(max_surface_change, 1e-12);
}

}  // namespace
