// Stoker's wet dam break as in Zheng et al. (Sec. 4.2): [0, 1] m, depths
// 1.0 m | 0.5 m at x = 0.5 m, t = 0.1 s, 100 x 3 cells, transmissive ends,
// walls on the long sides; run along x and along y. L1 error of h against
// the exact Riemann solution (rarefaction, middle state, shock). The
// two-phase mode without solids (an empty layer, its exchange after every
// step) must give the single-phase solver's answer.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "bench/shallow_water_dam_break.hpp"
#include "swe/solver_2d.hpp"
#include "swe/two_phase/two_phase_exchange.hpp"

namespace {

constexpr double g = 9.81, h_left = 1.0, h_right = 0.5, dam = 0.5, end_time = 0.1;

// L1 error of h along the long direction (x when along_x, else y).
double stoker_l1_error(bool along_x, const cosim::bench::ExactDamBreak& exact,
                       bool two_phase = false) {
  const int n = 100, across = 3;
  const double dx = 1.0 / n;
  const swe::Boundary open{swe::BoundaryKind::transmissive, 0.0},
      wall{swe::BoundaryKind::wall, 0.0};
  const swe::Grid2d grid = along_x ? swe::Grid2d{{0, 0}, {dx, dx}, {n, across}}
                                   : swe::Grid2d{{0, 0}, {dx, dx}, {across, n}};
  const swe::Boundaries2d sides = along_x ? swe::Boundaries2d{open, open, wall, wall}
                                          : swe::Boundaries2d{wall, wall, open, open};
  swe::Solver2d solver(grid, {}, {}, sides);
  std::vector<double> h(solver.cell_count());
  for (std::size_t c = 0; c < h.size(); ++c) {
    const int k = static_cast<int>(along_x ? c % n : c / across);
    h[c] = (k + 0.5) * dx < dam ? h_left : h_right;
  }
  solver.set_state(h, {}, {});
  std::optional<swe::TwoPhaseExchange> exchange;
  if (two_phase)
    exchange.emplace(solver, swe::TwoPhaseParameters{}, swe::UniformSources{},
                     swe::empty_solid_layer(h.size(), 2650.0), std::vector<double>(h.size(), 0.0));
  double t = 0.0;
  while (t < end_time) {
    const double dt = std::min(solver.stable_time_step(), end_time - t);
    solver.step(dt);
    if (exchange) exchange->after_step(solver, dt);
    t += dt;
  }
  double l1 = 0.0;
  for (std::size_t c = 0; c < h.size(); ++c) {
    const int k = static_cast<int>(along_x ? c % n : c / across);
    l1 += std::abs(solver.depth()[c] - exact.depth((k + 0.5) * dx, end_time)) * dx;
  }
  return l1 / across;  // per unit length of the 1 m channel, averaged over the rows
}

TEST(Swe2dStoker, MatchesTheExactDamBreakAlongXAndY) {
  const cosim::bench::ExactDamBreak exact(h_left, h_right, dam, g);
  const double tolerance = 5e-3;
  const double along_x = stoker_l1_error(true, exact), along_y = stoker_l1_error(false, exact);
  fmt::print(
      "Stoker dam break (h_m = {:.5f} m), t = {} s, 100 x 3 cells: L1(h) along x = {:.3e} m, "
      "along y = {:.3e} m (tolerance {:.0e} m)\n",
      exact.middle_depth(), end_time, along_x, along_y, tolerance);
  EXPECT_LE(along_x, tolerance);
  EXPECT_LE(along_y, tolerance);
  EXPECT_NEAR(along_x, along_y, 1e-14);  // the same code sweeps x and y
}

TEST(Swe2dStoker, TheTwoPhaseModeWithoutSolidsGivesTheSameAnswer) {
  const cosim::bench::ExactDamBreak exact(h_left, h_right, dam, g);
  const double single = stoker_l1_error(true, exact);
  const double two_phase = stoker_l1_error(true, exact, true);
  fmt::print(
      "Stoker dam break, two-phase mode without solids: L1(h) = {:.3e} m (single phase "
      "{:.3e} m, tolerance 5e-3 m)\n",
      two_phase, single);
  EXPECT_LE(two_phase, 5e-3);
  EXPECT_EQ(two_phase, single);
}

}  // namespace
