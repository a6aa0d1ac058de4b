#include <gtest/gtest.h>

#include <cmath>

#include "solver_1d_cases.hpp"

namespace {

using swe::BoundaryKind;

TEST(Solver1dBoundary, InflowDischargeAddsQdtPerStepIntoAUniformFlow) {
  const std::size_t n = 100;
  const double q = 0.5;
  for (auto [left, right, sign] :
       {std::tuple{swe::Boundary{BoundaryKind::inflow_discharge, q},
                   swe::Boundary{BoundaryKind::wall, 0.0}, 1.0},
        std::tuple{swe::Boundary{BoundaryKind::wall, 0.0},
                   swe::Boundary{BoundaryKind::inflow_discharge, q}, -1.0}}) {
    swe::Solver1d s(swe_test::uneven_edges(n, 0.0, 10.0), {}, {}, {left, right});
    s.set_state(std::vector<double>(n, 1.0), std::vector<double>(n, sign * q), {});
    for (int k = 0; k < 10; ++k) {
      const double v0 = s.totals().volume, dt = s.stable_time_step();
      s.step(dt);
      EXPECT_NEAR(s.totals().volume - v0, q * dt, 1e-12) << "step " << k << " inflow side " << sign;
    }
  }
}

TEST(Solver1dBoundary, InflowDischargeAddsQdtPerStepIntoStillWater) {
  // The boundary face passes exactly q, whatever the interior does.
  const std::size_t n = 100;
  const double q = 0.4;
  swe::Solver1d s(swe_test::uniform_edges(n, 0.0, 100.0), {}, {},
                  {{BoundaryKind::inflow_discharge, q}, {BoundaryKind::wall, 0.0}});
  s.set_state(std::vector<double>(n, 1.0), std::vector<double>(n, 0.0), {});
  for (int k = 0; k < 50; ++k) {
    const double v0 = s.totals().volume, dt = s.stable_time_step();
    s.step(dt);
    ASSERT_NEAR(s.totals().volume - v0, q * dt, 1e-12) << "step " << k;
  }
  EXPECT_GT(s.discharge_x()[0], 0.5 * q);
}

TEST(Solver1dBoundary, InflowEntersADryChannel) {
  const std::size_t n = 50;
  swe::Solver1d s(swe_test::uniform_edges(n, 0.0, 10.0), {}, {},
                  {{BoundaryKind::inflow_discharge, 0.2}, {BoundaryKind::wall, 0.0}});
  s.set_state(std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), {});
  double t = 0.0;
  while (t < 1.0) {
    const double dt = std::min(s.stable_time_step(), 0.01);
    s.step(dt);
    t += dt;
  }
  EXPECT_GT(s.totals().volume, 0.1);
  EXPECT_GT(s.depth()[0], 0.0);
}

TEST(Solver1dBoundary, FixedDepthDrivesTheBoundaryCellTowardsTheDepth) {
  const std::size_t n = 100;
  struct Case {
    swe::Boundaries1d b;
    std::size_t cell;
    double start, target;
  };
  for (const Case& c :
       {Case{{{BoundaryKind::wall, 0.0}, {BoundaryKind::fixed_depth, 0.6}}, n - 1, 1.0, 0.6},
        Case{{{BoundaryKind::fixed_depth, 0.8}, {BoundaryKind::wall, 0.0}}, 0, 0.5, 0.8}}) {
    swe::Solver1d s(swe_test::uneven_edges(n, 0.0, 20.0), {}, {}, c.b);
    s.set_state(std::vector<double>(n, c.start), std::vector<double>(n, 0.0), {});
    const double v0 = s.totals().volume;
    double t = 0.0;
    while (t < 2.0) {
      const double dt = s.stable_time_step();
      s.step(dt);
      t += dt;
    }
    const double h = s.depth()[c.cell];
    std::cout << "fixed depth " << c.target << ": boundary cell " << h << "\n";
    EXPECT_NEAR(h, c.target, 0.02 * std::abs(c.start - c.target));
    EXPECT_EQ(s.totals().volume > v0, c.target > c.start);
  }
}

}  // namespace
