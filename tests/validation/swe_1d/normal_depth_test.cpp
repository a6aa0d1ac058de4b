#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "swe/solver_1d.hpp"

// Steady uniform flow with Manning friction: q = 1 m^2/s enters a 2 km
// channel of slope S = 1e-3 and Manning n = 0.03 s/m^(1/3) and leaves over a
// fixed depth h_n (a transmissive end, whose ghost bed is flat, feels only
// half the slope in its last cell and backs water up: h = 2.0 m there after
// 6000 s). From a start at h_n / 2 at rest, the depth along the channel
// settles at the normal depth
// h_n = (n q / sqrt(S))^(3/5), where g h S balances g n^2 u |u| / h^(1/3)
// (Zheng et al., eqs. 8 and 24).
namespace {

TEST(ManningNormalDepth, SteadyUniformFlowOnASlope) {
  constexpr std::size_t n = 200;
  constexpr double length = 2000.0, slope = 1e-3, q = 1.0;
  swe::Physics physics;
  physics.manning = 0.03;
  const double h_normal = std::pow(physics.manning * q / std::sqrt(slope), 0.6);
  std::vector<double> edges(n + 1), bed(n);
  for (std::size_t i = 0; i <= n; ++i)
    edges[i] = length * static_cast<double>(i) / static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) bed[i] = -slope * 0.5 * (edges[i] + edges[i + 1]);
  swe::Solver1d s(
      edges, physics, {},
      {{swe::BoundaryKind::inflow_discharge, q}, {swe::BoundaryKind::fixed_depth, h_normal}});
  s.set_bed(bed);
  s.set_state(std::vector<double>(n, 0.5 * h_normal), std::vector<double>(n, 0.0), {});
  double t = 0.0;
  while (t < 6000.0) {
    const double dt = s.stable_time_step();
    s.step(dt);
    t += dt;
  }
  for (std::size_t cell : {n / 4, n / 2}) {
    const double h = s.depth()[cell], discharge = s.discharge_x()[cell];
    const double error = std::abs(h - h_normal) / h_normal;
    fmt::print(
        "normal depth {:.5f} m; depth at x = {:.0f} m: {:.5f} m (error {:.3f} %, tolerance 1 %), "
        "discharge {:.5f} m^2/s\n",
        h_normal, s.edges()[cell], h, 100.0 * error, discharge);
    EXPECT_LE(error, 0.01);
    EXPECT_NEAR(discharge, q, 0.01 * q);
  }
}

}  // namespace
