// Radial dam break on [-1, 1]^2 (cell centres symmetric about both axes and
// the diagonals): a column h = 1 m inside r < 0.3 m over 0.5 m of water (wet
// variant) or a dry bed (dry variant), stopped before the waves reach the
// walls. The profiles along +x, -x, +y and -y must agree to round-off, and
// the profile along the diagonal must follow the axis profile at the same
// radius (isotropy of the Cartesian scheme, a loose check).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "swe/solver_2d.hpp"

namespace {

#ifdef COSIM_FULL_VALIDATION
constexpr int cells_per_side = 400;
#else
constexpr int cells_per_side = 200;
#endif

struct Outcome {
  double symmetry_deviation =
      0.0;  // max |profile - +x profile| / max h, over -x, +y, -y (h and normal discharge)
  double diagonal_mean_deviation = 0.0;  // mean |h_diag - h_axis(r)| / (h_max - h_min)
  double diagonal_max_deviation = 0.0;
};

Outcome radial_dam_break(double outside_depth, double end_time) {
  const int n = cells_per_side, half = n / 2;
  const double dx = 2.0 / n;
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0};
  swe::Solver2d solver({{-1.0, -1.0}, {dx, dx}, {n, n}}, {}, {}, {wall, wall, wall, wall});
  std::vector<double> h;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = -1.0 + (i + 0.5) * dx, y = -1.0 + (j + 0.5) * dx;
      h.push_back(x * x + y * y < 0.09 ? 1.0 : outside_depth);
    }
  }
  solver.set_state(h, {}, {});
  double t = 0.0;
  while (t < end_time) {
    const double dt = std::min(solver.stable_time_step(), end_time - t);
    solver.step(dt);
    t += dt;
  }
  const auto depth = solver.depth();
  const auto qx = solver.discharge_x();
  const auto qy = solver.discharge_y();
  auto at = [n](int i, int j) { return static_cast<std::size_t>(i + n * j); };
  // Nothing may have reached the walls.
  EXPECT_EQ(depth[at(0, half)], outside_depth);
  EXPECT_EQ(depth[at(half, n - 1)], outside_depth);

  const double h_max = *std::max_element(depth.begin(), depth.end());
  Outcome o;
  for (int k = 0; k < half; ++k) {
    const double h0 = depth[at(half + k, half)], q = qx[at(half + k, half)];
    const double deviations[] = {
        depth[at(half - 1 - k, half)] - h0, -qx[at(half - 1 - k, half)] - q,  // -x
        depth[at(half, half + k)] - h0,     qy[at(half, half + k)] - q,       // +y
        depth[at(half, half - 1 - k)] - h0, -qy[at(half, half - 1 - k)] - q,  // -y
    };
    for (double d : deviations)
      o.symmetry_deviation = std::max(o.symmetry_deviation, std::abs(d) / h_max);
  }
  // Diagonal cell (half + k, half + k) against the +x axis profile at its radius.
  std::vector<double> axis_radius, axis_depth;
  for (int k = 0; k < half; ++k) {
    axis_radius.push_back(std::hypot((k + 0.5) * dx, 0.5 * dx));
    axis_depth.push_back(depth[at(half + k, half)]);
  }
  const double range = h_max - outside_depth;
  int compared = 0;
  for (int k = 0; (k + 0.5) * dx * std::sqrt(2.0) < axis_radius.back(); ++k) {
    const double r = (k + 0.5) * dx * std::sqrt(2.0);
    const auto above = std::upper_bound(axis_radius.begin(), axis_radius.end(), r);
    if (above == axis_radius.begin()) continue;
    const std::size_t m = static_cast<std::size_t>(above - axis_radius.begin());
    const double w = (r - axis_radius[m - 1]) / (axis_radius[m] - axis_radius[m - 1]);
    const double axis = (1.0 - w) * axis_depth[m - 1] + w * axis_depth[m];
    const double deviation = std::abs(depth[at(half + k, half + k)] - axis) / range;
    o.diagonal_mean_deviation += deviation;
    o.diagonal_max_deviation = std::max(o.diagonal_max_deviation, deviation);
    ++compared;
  }
  o.diagonal_mean_deviation /= compared;
  return o;
}

constexpr double symmetry_tolerance = 1e-10;

TEST(Swe2dRadialDamBreak, WetBedStaysRadiallySymmetric) {
  const double mean_tolerance = 0.02;
  const Outcome o = radial_dam_break(0.5, 0.15);
  fmt::print(
      "radial dam break 1.0 | 0.5 m, {}^2 cells, t = 0.15 s: axis symmetry deviation {:.2e} "
      "(tolerance {:.0e}); diagonal vs axis: mean {:.2e} (tolerance {:.0e}), max {:.2e} of the "
      "jump\n",
      cells_per_side, o.symmetry_deviation, symmetry_tolerance, o.diagonal_mean_deviation,
      mean_tolerance, o.diagonal_max_deviation);
  EXPECT_LE(o.symmetry_deviation, symmetry_tolerance);
  EXPECT_LE(o.diagonal_mean_deviation, mean_tolerance);
}

TEST(Swe2dRadialDamBreak, DryBedStaysRadiallySymmetric) {
  const double mean_tolerance = 0.03;
  const Outcome o = radial_dam_break(0.0, 0.08);
  fmt::print(
      "radial dam break 1.0 m | dry, {}^2 cells, t = 0.08 s: axis symmetry deviation {:.2e} "
      "(tolerance {:.0e}); diagonal vs axis: mean {:.2e} (tolerance {:.0e}), max {:.2e} of the "
      "jump\n",
      cells_per_side, o.symmetry_deviation, symmetry_tolerance, o.diagonal_mean_deviation,
      mean_tolerance, o.diagonal_max_deviation);
  EXPECT_LE(o.symmetry_deviation, symmetry_tolerance);
  EXPECT_LE(o.diagonal_mean_deviation, mean_tolerance);
}

}  // namespace
