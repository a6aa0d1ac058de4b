#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver_2d_fixture.hpp"
#include "swe/solver_2d.hpp"

namespace {

TEST(Solver2dBoundaries, InflowDischargeAddsQTimesWidthPerStep) {
  // Uniform stream h = 1 m, q = 0.4 m^2/s entering at x_min; the wall at
  // x_max is too far for its reflection to reach the inlet in 5 steps.
  const double q = 0.4, h = 1.0;
  const swe::Grid2d grid{{0, 0}, {0.1, 0.1}, {100, 6}};
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0},
      inflow{swe::BoundaryKind::inflow_discharge, q};
  swe::Solver2d solver(grid, {}, {}, {inflow, wall, wall, wall});
  const std::size_t n = solver.cell_count();
  solver.set_state(std::vector<double>(n, h), std::vector<double>(n, q), {});
  const double width = 0.6;
  for (int step = 0; step < 5; ++step) {
    const double volume = solver.totals().volume, dt = solver.stable_time_step();
    solver.step(dt);
    EXPECT_NEAR(solver.totals().volume - volume, q * width * dt, 1e-12 * q * width * dt)
        << "step " << step;
  }
}

TEST(Solver2dBoundaries, InflowOnYMaxEntersAlongMinusY) {
  const swe::Grid2d grid{{0, 0}, {0.1, 0.1}, {5, 40}};
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0},
      inflow{swe::BoundaryKind::inflow_discharge, 0.2};
  swe::Solver2d solver(grid, {}, {}, {wall, wall, wall, inflow});
  solver.set_state(std::vector<double>(solver.cell_count(), 0.0), {},
                   {});  // dry: critical depth enters
  const double dt = 0.01;
  for (int step = 0; step < 20; ++step) solver.step(dt);
  EXPECT_GT(solver.totals().volume, 0.0);
  EXPECT_LT(solver.totals().momentum_y, 0.0);
  EXPECT_EQ(solver.depth()[0], 0.0);  // far end still dry
}

TEST(Solver2dBoundaries, FixedDepthDrainsTowardsItsLevel) {
  // A basin at 1 m with the x_max side held at 0.5 m loses water, and the
  // outflow runs towards +x.
  const swe::Grid2d grid{{0, 0}, {0.05, 0.05}, {40, 4}};
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0},
      level{swe::BoundaryKind::fixed_depth, 0.5};
  swe::Solver2d solver(grid, {}, {}, {wall, level, wall, wall});
  solver.set_state(std::vector<double>(solver.cell_count(), 1.0), {}, {});
  const double volume = solver.totals().volume;
  swe_2d_test::run_steps(solver, 100);
  EXPECT_LT(solver.totals().volume, 0.95 * volume);
  EXPECT_GT(solver.discharge_x()[39], 0.0);
  EXPECT_EQ(solver.totals().momentum_y, 0.0);
}

TEST(Solver2dBoundaries, WallsReflectWithoutLosingWater) {
  const swe::Grid2d grid{{0, 0}, {0.05, 0.05}, {20, 20}};
  swe::Solver2d solver(grid, {}, {}, swe_2d_test::all_sides(swe::BoundaryKind::wall));
  const std::size_t n = solver.cell_count();
  solver.set_state(std::vector<double>(n, 0.5), std::vector<double>(n, 0.5),
                   std::vector<double>(n, -0.25));
  const double volume = solver.totals().volume;
  swe_2d_test::run_steps(solver, 200);
  EXPECT_NEAR(solver.totals().volume, volume, 1e-13 * volume);
  EXPECT_LT(std::abs(solver.totals().momentum_x), 0.5 * 0.5 * 1.0);  // walls took momentum away
}

TEST(Solver2dBoundaries, TransmissiveSidesLetAStreamLeave) {
  const swe::Grid2d grid{{0, 0}, {0.05, 0.05}, {30, 3}};
  const swe::Boundary open{swe::BoundaryKind::transmissive, 0.0},
      wall{swe::BoundaryKind::wall, 0.0};
  swe::Solver2d solver(grid, {}, {}, {wall, open, wall, wall});
  const std::size_t n = solver.cell_count();
  solver.set_state(std::vector<double>(n, 0.3), std::vector<double>(n, 0.3 * 0.5), {});
  const double volume = solver.totals().volume;
  swe_2d_test::run_steps(solver, 50);
  EXPECT_LT(solver.totals().volume, volume);
}

}  // namespace
