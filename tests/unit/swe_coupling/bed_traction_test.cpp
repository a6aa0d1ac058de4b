#include "swe/coupling/bed_traction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "cosim/error.hpp"
#include "swe/solver_1d.hpp"
#include "swe/solver_2d.hpp"

namespace {

constexpr double g = 9.81, rho = 1000.0;

swe::Solver1d line(std::size_t cells, double length) {
  std::vector<double> edges(cells + 1);
  for (std::size_t i = 0; i <= cells; ++i)
    edges[i] = length * static_cast<double>(i) / static_cast<double>(cells);
  return swe::Solver1d(edges, swe::Physics{}, swe::Scheme{}, {});
}

TEST(BedTraction, IsTheWaterWeightOnAFlatBedAtRest) {
  swe::Solver1d s = line(10, 1.0);
  s.set_bed(std::vector<double>(10, 0.2));
  s.set_state(std::vector<double>(10, 0.7), std::vector<double>(10, 0.0), {});
  const auto t = swe::bed_traction(s, {});
  ASSERT_EQ(t.size(), 20u);
  for (std::size_t c = 0; c < 10; ++c) {
    EXPECT_EQ(t[2 * c], 0.0);
    EXPECT_DOUBLE_EQ(t[2 * c + 1], -rho * g * 0.7);
  }
}

TEST(BedTraction, PushesABedStepWithTheHydrostaticThrust) {
  // 1 m of water against a 0.5 m step: the water's force on the step's face
  // is rho g (1^2 - 0.5^2) / 2 towards -x, whatever the cell widths.
  swe::Solver1d s = line(4, 2.0);
  s.set_bed(std::vector<double>{0.5, 0.5, 0.0, 0.0});
  s.set_state(std::vector<double>{0.5, 0.5, 1.0, 1.0}, std::vector<double>(4, 0.0), {});
  const auto t = swe::bed_traction(s, {});
  double force = 0.0;
  for (std::size_t c = 0; c < 4; ++c) force += t[2 * c] * 0.5;
  EXPECT_NEAR(force, -rho * g * (1.0 - 0.25) / 2.0, 1e-9);
  // An emerged step (dry top) gets the thrust of the water's own depth only.
  s.set_state(std::vector<double>{0.0, 0.0, 0.3, 0.3}, std::vector<double>(4, 0.0), {});
  const auto dry = swe::bed_traction(s, {});
  force = 0.0;
  for (std::size_t c = 0; c < 4; ++c) force += dry[2 * c] * 0.5;
  EXPECT_NEAR(force, -rho * g * 0.09 / 2.0, 1e-9);
}

TEST(BedTraction, AddsManningShearAlongTheFlow) {
  swe::Physics physics;
  physics.manning = 0.03;
  swe::Solver1d s(std::vector<double>{0.0, 1.0, 2.0}, physics, swe::Scheme{}, {});
  s.set_bed(std::vector<double>(2, 0.0));
  s.set_state(std::vector<double>{0.5, 0.5}, std::vector<double>{-0.5, -0.5}, {});
  const auto t = swe::bed_traction(s, {});
  // u = -1 m/s: tau = rho g n^2 u |u| / h^(1/3), along -x.
  EXPECT_NEAR(t[0], -rho * g * 0.03 * 0.03 / std::cbrt(0.5), 1e-9);
}

TEST(BedTraction, ExcessPressureIsTheWavesPushOverTheInitialSurfaceOnWetCellsOnly) {
  swe::Solver1d s = line(4, 4.0);
  s.set_bed(std::vector<double>{1.2, 0.0, 0.0, 0.5});
  s.set_state(std::vector<double>{0.0, 1.1, 0.9, 1.3}, std::vector<double>(4, 0.0), {});
  swe::CouplingSpec spec;
  spec.pressure = swe::BedPressure::excess;
  spec.initial_surface = {1.2, 1.0, 1.0, 2.0};  // the last cell started under 1.5 m of water
  const auto t = swe::bed_traction(s, spec);
  EXPECT_EQ(t[1], 0.0);                     // dry cell
  EXPECT_NEAR(t[3], -rho * g * 0.1, 1e-9);  // crest
  EXPECT_EQ(t[5], 0.0);                     // a trough does not pull
  EXPECT_EQ(t[7], 0.0);                     // nor does water draining off the cell
  EXPECT_EQ(t[0], 0.0);                     // no horizontal pressure
  spec.initial_surface.pop_back();
  EXPECT_THROW(swe::bed_traction(s, spec), cosim::Error);
}

TEST(BedTraction, HasThreeComponentsIn2DAndBalancesALakeAtRestInTotal) {
  swe::Grid2d grid;
  grid.cells = {6, 5};
  grid.spacing = {0.2, 0.25};
  swe::Solver2d s(grid, swe::Physics{}, swe::Scheme{}, {});
  std::vector<double> bed(30), h(30);
  for (std::size_t c = 0; c < 30; ++c) {
    const double x = 0.2 * (static_cast<double>(c % 6) + 0.5),
                 y = 0.25 * (static_cast<double>(c / 6) + 0.5);
    bed[c] = 0.3 * std::exp(-((x - 0.6) * (x - 0.6) + (y - 0.6) * (y - 0.6)));
    h[c] = 0.5 - bed[c];
  }
  s.set_bed(bed);
  s.set_state(h, std::vector<double>(30, 0.0), std::vector<double>(30, 0.0));
  const auto t = swe::bed_traction(s, {});
  ASSERT_EQ(t.size(), 90u);
  // The vertical load is the water's weight.
  double weight = 0.0;
  for (std::size_t c = 0; c < 30; ++c) weight += t[3 * c + 2] * 0.05;
  EXPECT_NEAR(weight, -rho * g * std::accumulate(h.begin(), h.end(), 0.0) * 0.05, 1e-6);
}

}  // namespace
