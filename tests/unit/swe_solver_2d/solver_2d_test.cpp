#include "swe/solver_2d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "solver_2d_fixture.hpp"

namespace {

using swe_2d_test::all_sides;
using swe_2d_test::run_steps;
using swe_2d_test::sample;

TEST(Solver2d, DescribesItsCells) {
  const swe::Grid2d grid{{-1.0, 2.0}, {0.5, 0.25}, {4, 3}};
  const swe::Solver2d solver(grid, {}, {}, all_sides(swe::BoundaryKind::wall));
  EXPECT_EQ(solver.cell_count(), 12u);
  EXPECT_DOUBLE_EQ(solver.cell_size(5), 0.125);
  const auto mesh = std::get<cosim::UniformGrid>(solver.cells());
  EXPECT_EQ(mesh.dim, 2);
  EXPECT_EQ(mesh.location, cosim::GridLocation::cell);
  EXPECT_EQ(mesh.cells[0], 4);
  EXPECT_EQ(mesh.cells[1], 3);
  EXPECT_DOUBLE_EQ(mesh.origin[1], 2.0);
  EXPECT_DOUBLE_EQ(mesh.spacing[1], 0.25);
  EXPECT_EQ(solver.cell_at(-0.9, 2.1), 0u);
  EXPECT_EQ(solver.cell_at(0.1, 2.3), 2u + 4u * 1u);
  EXPECT_EQ(solver.cell_at(1.0, 2.75), 11u);  // upper corner: the last cell
  EXPECT_EQ(solver.cell_at(-1.1, 2.1), 12u);
  EXPECT_EQ(solver.cell_at(0.0, 2.8), 12u);
}

TEST(Solver2d, RejectsABadGrid) {
  auto message_of = [](const swe::Grid2d& grid) {
    try {
      swe::Solver2d solver(grid, {}, {}, all_sides(swe::BoundaryKind::wall));
    } catch (const cosim::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message_of({{0, 0}, {0.0, 1.0}, {4, 4}}).find("spacing in x"), std::string::npos);
  EXPECT_NE(message_of({{0, 0}, {1.0, -2.0}, {4, 4}}).find("-2"), std::string::npos);
  EXPECT_NE(message_of({{0, 0}, {1.0, 1.0}, {4, 0}}).find("cell count in y"), std::string::npos);
  EXPECT_THROW(
      swe::Solver2d({{0, 0}, {1.0, 1.0}, {-3, 4}}, {}, {}, all_sides(swe::BoundaryKind::wall)),
      cosim::InputError);
}

TEST(Solver2d, RejectsNegativeDepthsAndWrongSizes) {
  swe::Solver2d solver({{0, 0}, {1.0, 1.0}, {3, 2}}, {}, {}, all_sides(swe::BoundaryKind::wall));
  std::vector<double> h(6, 1.0), q(6, 0.0);
  h[4] = -1e-3;
  try {
    solver.set_state(h, q, q);
    FAIL() << "negative depth accepted";
  } catch (const cosim::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell 4"), std::string::npos) << e.what();
  }
  h[4] = 1.0;
  EXPECT_THROW(solver.set_state(std::vector<double>(5, 1.0), q, q), cosim::InputError);
  EXPECT_THROW(solver.set_state(h, std::vector<double>(7, 0.0), q), cosim::InputError);
  EXPECT_THROW(solver.set_bed(std::vector<double>(2, 0.0)), cosim::InputError);
  EXPECT_NO_THROW(solver.set_state(h, {}, {}));
}

TEST(Solver2d, KeepsAConstantStateConstant) {
  const swe::Grid2d grid{{0, 0}, {0.1, 0.2}, {12, 9}};
  swe::Solver2d solver(grid, {}, {}, all_sides(swe::BoundaryKind::transmissive));
  const std::size_t n = solver.cell_count();
  solver.set_state(std::vector<double>(n, 0.8), std::vector<double>(n, 0.8 * 0.3),
                   std::vector<double>(n, -0.8 * 0.2));
  run_steps(solver, 20);
  for (std::size_t c = 0; c < n; ++c) {
    EXPECT_NEAR(solver.depth()[c], 0.8, 1e-14);
    EXPECT_NEAR(solver.discharge_x()[c], 0.24, 1e-14);
    EXPECT_NEAR(solver.discharge_y()[c], -0.16, 1e-14);
  }
}

TEST(Solver2d, ConservesVolumeWithWallsFromAStateWithDryCells) {
  const swe::Grid2d grid{{0, 0}, {0.05, 0.05}, {40, 30}};
  swe::Solver2d solver(grid, {}, {}, all_sides(swe::BoundaryKind::wall));
  solver.set_bed(sample(grid, [](double x, double y) {
    return 0.3 * std::exp(-20 * ((x - 1.2) * (x - 1.2) + (y - 0.7) * (y - 0.7)));
  }));
  solver.set_state(sample(grid, [](double x, double) { return x < 0.6 ? 1.0 : 0.0; }),
                   sample(grid, [](double x, double) { return x < 0.6 ? 0.2 : 0.0; }), {});
  const double volume = solver.totals().volume;
  run_steps(solver, 300);
  EXPECT_NEAR(solver.totals().volume, volume, 1e-13 * volume);
  EXPECT_GE(*std::min_element(solver.depth().begin(), solver.depth().end()), 0.0);
}

TEST(Solver2d, KeepsALakeAtRestAroundAnEmergedIsland) {
  const swe::Grid2d grid{{-1, -1}, {0.05, 0.05}, {40, 40}};
  swe::Solver2d solver(grid, {}, {}, all_sides(swe::BoundaryKind::wall));
  const auto bed =
      sample(grid, [](double x, double y) { return 0.8 * std::exp(-5 * (x * x + 2 * y * y)); });
  std::vector<double> h(bed.size());
  for (std::size_t c = 0; c < h.size(); ++c) h[c] = std::max(0.0, 0.5 - bed[c]);
  ASSERT_TRUE(std::count(h.begin(), h.end(), 0.0) > 10);
  solver.set_bed(bed);
  solver.set_state(h, {}, {});
  run_steps(solver, 200);
  EXPECT_LE(swe_2d_test::max_speed(solver), 1e-12);
  for (std::size_t c = 0; c < h.size(); ++c) EXPECT_NEAR(solver.depth()[c], h[c], 1e-13);
}

TEST(Solver2d, SetBedKeepsDepthAndVolume) {
  const swe::Grid2d grid{{0, 0}, {0.1, 0.1}, {10, 10}};
  swe::Solver2d solver(grid, {}, {}, all_sides(swe::BoundaryKind::wall));
  solver.set_state(sample(grid, [](double x, double y) { return 0.5 + 0.1 * x * y; }), {}, {});
  run_steps(solver, 5);
  const std::vector<double> depth(solver.depth().begin(), solver.depth().end());
  const double volume = solver.totals().volume;
  solver.set_bed(sample(grid, [](double x, double) { return 0.2 * x; }));
  EXPECT_EQ(solver.totals().volume, volume);
  EXPECT_TRUE(std::equal(depth.begin(), depth.end(), solver.depth().begin()));
  EXPECT_DOUBLE_EQ(solver.bed()[9], 0.2 * 0.95);
}

TEST(Solver2d, ManningFrictionDecaysMomentumAsEquation36) {
  const swe::Grid2d grid{{0, 0}, {0.1, 0.1}, {6, 5}};
  swe::Physics physics;
  physics.manning = 0.03;
  swe::Solver2d solver(grid, physics, {}, all_sides(swe::BoundaryKind::transmissive));
  const double h = 0.5, u = 1.0, v = 0.5, dt = 0.01;
  const std::size_t n = solver.cell_count();
  solver.set_state(std::vector<double>(n, h), std::vector<double>(n, h * u),
                   std::vector<double>(n, h * v));
  solver.step(dt);
  const double factor =
      1.0 / (1.0 + dt * physics.gravity * 0.03 * 0.03 * std::hypot(u, v) / std::pow(h, 4.0 / 3.0));
  ASSERT_LT(factor, 0.9999);
  for (std::size_t c = 0; c < n; ++c) {
    EXPECT_NEAR(solver.depth()[c], h, 1e-14);
    EXPECT_NEAR(solver.discharge_x()[c], h * u * factor, 1e-14);
    EXPECT_NEAR(solver.discharge_y()[c], h * v * factor, 1e-14);
  }
}

TEST(Solver2d, KeepsDepthsNonNegativeInADryBedDamBreak) {
  for (auto flux : {swe::FluxKind::hllc, swe::FluxKind::hll, swe::FluxKind::roe}) {
    const swe::Grid2d grid{{0, 0}, {0.02, 0.02}, {50, 50}};
    swe::Scheme scheme;
    scheme.flux = flux;
    swe::Solver2d solver(grid, {}, scheme, all_sides(swe::BoundaryKind::wall));
    solver.set_state(
        sample(grid, [](double x, double y) { return x < 0.4 && y < 0.5 ? 1.0 : 0.0; }), {}, {});
    const double volume = solver.totals().volume;
    for (int n = 0; n < 150; ++n) {
      solver.step(solver.stable_time_step());
      const auto h = solver.depth();
      ASSERT_GE(*std::min_element(h.begin(), h.end()), 0.0)
          << swe::to_string(flux) << " step " << n;
    }
    EXPECT_NEAR(solver.totals().volume, volume, 1e-13 * volume) << swe::to_string(flux);
    EXPECT_TRUE(std::isfinite(solver.totals().momentum_x));
  }
}

TEST(Solver2d, TakesAnInfiniteStepWhenEverythingIsDry) {
  swe::Solver2d solver({{0, 0}, {1.0, 1.0}, {3, 3}}, {}, {}, all_sides(swe::BoundaryKind::wall));
  EXPECT_EQ(solver.stable_time_step(), std::numeric_limits<double>::infinity());
  std::vector<double> h(9, 0.0);
  h[4] = 1.0;
  solver.set_state(h, {}, {});
  // Cell 4 has dry neighbours: its waves count 2 c in each direction.
  EXPECT_DOUBLE_EQ(solver.stable_time_step(), 0.5 / (2 * 2 * std::sqrt(9.81)));
}

}  // namespace
