#include "mpm/depth_averaged/depth_averaged_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "cosim/error.hpp"

namespace mpm {
namespace {

constexpr double deg = std::numbers::pi / 180.0;
constexpr double g = 9.81;

DepthAveragedMaterial sand(double basal_friction_deg, double cohesion = 0.0) {
  DepthAveragedMaterial m;
  m.name = "sand";
  m.density = 2000.0;
  m.internal_friction_angle = 30.0 * deg;
  m.basal_friction_angle = basal_friction_deg * deg;
  m.cohesion = cohesion;
  return m;
}

DepthAveragedSettings ground(double inclination_deg, int nx, int ny, double dx,
                             EarthPressureModel model = EarthPressureModel::isotropic) {
  DepthAveragedSettings s;
  s.grid.origin = Vec<2>::Zero();
  s.grid.spacing = Vec<2>::Constant(dx);
  s.grid.cells = {nx, ny};
  s.terrain = Terrain(inclination_deg * deg, g);
  s.earth_pressure = EarthPressure(model);
  return s;
}

DepthAveragedSolver block(const DepthAveragedSettings& s, const DepthAveragedMaterial& m,
                          const Vec<2>& lower, const Vec<2>& upper, double depth,
                          const Vec<2>& v = Vec<2>::Zero()) {
  DepthAveragedParticles p;
  p.seed(
      lower, upper, s.grid.spacing, 2, [&](const Vec<2>&) { return depth; }, m.density, 0, v);
  return DepthAveragedSolver(s, {m}, p);
}

// A layer of uniform depth filling the grid between slip walls on level
// ground: the Gauss-point seeding gives every node the same depth, so no
// thrust gradient moves it.
TEST(DepthAveragedSolver, AUniformLayerOnLevelGroundStaysAtRest) {
  const auto s = ground(0.0, 8, 6, 0.5);
  auto solver = block(s, sand(0.0), {0.0, 0.0}, {4.0, 3.0}, 0.7);
  for (double h : solver.nodal_depth()) EXPECT_NEAR(h, 0.7, 1e-14);
  for (int k = 0; k < 50; ++k) solver.step(1e-3);
  double fastest = 0.0;
  for (const auto& v : solver.particles().velocity) fastest = std::max(fastest, v.norm());
  EXPECT_LT(fastest, 1e-12);
}

// The same layer at the bottom of a lake, and a partly emerged one: the
// lake's surface is level, so it pushes no column sideways.
TEST(DepthAveragedSolver, ALayerInALakeAtRestStaysAtRest) {
  for (const double level : {5.0, 0.3}) {
    auto s = ground(0.0, 8, 6, 0.5);
    s.still_water = StillWater{1000.0, level};
    auto solver = block(s, sand(0.0), {0.0, 0.0}, {4.0, 3.0}, 0.7);
    for (int k = 0; k < 50; ++k) solver.step(1e-3);
    double fastest = 0.0;
    for (const auto& v : solver.particles().velocity) fastest = std::max(fastest, v.norm());
    EXPECT_LT(fastest, 1e-12) << "level " << level;
  }
}

// A lake's surface on the inclined plane rises along x at tan(theta): the
// nodes' heights reproduce it exactly between the walls.
TEST(DepthAveragedSolver, AStillLakesSurfaceIsLevelInTheWorld) {
  auto s = ground(30.0, 10, 4, 0.5);
  s.still_water = StillWater{1000.0, 2.0};
  const auto solver = block(s, sand(40.0), {1.0, 0.0}, {2.0, 2.0}, 0.5);
  for (const double x : {0.1, 2.3, 4.9}) {
    const double expected = (2.0 + x * std::sin(30.0 * deg)) / std::cos(30.0 * deg);
    EXPECT_NEAR(solver.fluid_surface_at({x, 1.0}), expected, 1e-12) << "x " << x;
  }
}

// B = 1 relieves the base by the fluid's whole pressure, B = 0 by none
// (eq. 39). On a 40 deg slope with delta 30 deg a dry block slides; deep in
// water buoyancy halves its drive (rho_f / rho = 1/2), so with B = 0 the
// friction on its full weight holds it, and with B = 1 it slides.
TEST(DepthAveragedSolver, ASubmergedBlockIsHeldWithBZeroAndSlidesWithBOne) {
  for (const double B : {0.0, 1.0}) {
    auto s = ground(40.0, 20, 8, 0.5);
    s.still_water = StillWater{1000.0, 50.0};
    auto m = sand(30.0, 1e5);
    m.basal_pressure_factor = B;
    auto solver = block(s, m, {3.0, 1.0}, {5.0, 3.0}, 1.0);
    for (int k = 0; k < 100; ++k) solver.step(1e-3);
    double fastest = 0.0;
    for (const auto& v : solver.particles().velocity) fastest = std::max(fastest, v.norm());
    if (B == 0.0)
      EXPECT_EQ(fastest, 0.0);
    else
      EXPECT_GT(fastest, 0.05);
  }
}

// The same physics when the slope is the bed's (a catchment in plan view,
// theta = 0): a rigid block deep in a still lake on a bed falling at
// tan(alpha) = 0.5 accelerates at g ((1 - gamma) tan(alpha) - (1 - B gamma)
// tan(delta)), gamma = rho_f / rho (the shallow-topography form of the
// inclined-plane formula): buoyancy takes its share of the drive whatever B.
TEST(DepthAveragedSolver, BuoyancyTakesItsShareOfTheDriveOnASlopingBed) {
  std::vector<double> bed;
  for (int row = 0; row < 9; ++row)
    for (int column = 0; column < 25; ++column) bed.push_back(20.0 - 0.5 * 0.5 * column);
  for (const double B : {0.0, 1.0}) {
    auto s = ground(0.0, 24, 8, 0.5);
    s.terrain = Terrain(0.0, g, RasterGrid(25, 9, Vec<2>::Zero(), 0.5, bed));
    s.still_water = StillWater{1000.0, 100.0};
    auto m = sand(10.0, 1e6);  // rigid
    m.basal_pressure_factor = B;
    auto solver = block(s, m, {3.0, 1.0}, {5.0, 3.0}, 1.0);
    const double dt = 1e-3;
    for (int k = 0; k < 200; ++k) solver.step(dt);
    const double gamma = 0.5;
    const double a = g * ((1.0 - gamma) * 0.5 - (1.0 - B * gamma) * std::tan(10.0 * deg));
    const double v = solver.particles().momentum()[0] / solver.particles().total_mass();
    EXPECT_NEAR(v, a * 0.2, 1e-3 * a * 0.2) << "B = " << B;
  }
}

// A block sliding down a 30 deg plane into an obstacle across half its
// width: the half that meets it stops in front of it, the other half slides
// past; no point gets into the obstacle.
TEST(DepthAveragedSolver, AnObstacleStopsTheMassThatMeetsIt) {
  auto s = ground(30.0, 40, 16, 0.25);
  s.obstacles.push_back({{5.0, 0.0}, {5.5, 2.0}});
  auto solver = block(s, sand(20.0, 1e5), {2.0, 0.5}, {3.5, 3.5}, 0.5);
  solver.advance_to(2.2);
  double blocked_front = 0.0, free_front = 0.0;
  for (const auto& x : solver.particles().position) {
    EXPECT_FALSE(x[0] > 5.0 + 0.25 && x[0] < 5.5 && x[1] < 2.0 - 0.25)
        << "a point at (" << x[0] << ", " << x[1] << ") inside the obstacle";
    (x[1] < 1.5 ? blocked_front : free_front) =
        std::max(x[1] < 1.5 ? blocked_front : free_front, x[0]);
  }
  EXPECT_LT(blocked_front, 5.25);
  EXPECT_GT(free_front, 6.0);
  s.obstacles.front().max = {4.0, 1.0};
  EXPECT_THROW(block(s, sand(20.0), {2.0, 0.5}, {3.5, 3.5}, 0.5), std::invalid_argument);
}

TEST(DepthAveragedSolver, RefusesAFluidSurfaceOfTheWrongSizeOrNotFinite) {
  const auto s = ground(0.0, 8, 6, 0.5);
  auto solver = block(s, sand(0.0), {0.0, 0.0}, {4.0, 3.0}, 0.7);
  EXPECT_THROW(solver.set_fluid_surface(1000.0, std::vector<double>(3, 1.0)),
               std::invalid_argument);
  std::vector<double> surface(solver.nodal_depth().size(), 1.0);
  EXPECT_THROW(solver.set_fluid_surface(0.0, surface), std::invalid_argument);
  surface[4] = std::nan("");
  EXPECT_THROW(solver.set_fluid_surface(1000.0, surface), std::invalid_argument);
}

// Eq. 28: the structures break up as exp(-eps_v / ((1 - D) eps_f)) while the
// column dilates, and not while it is compressed.
TEST(DepthAveragedMaterial, StructuresBreakUpAsTheColumnDilates) {
  auto m = sand(20.0, 1e4);
  m.degradation = CohesionDegradation(0.05);
  EXPECT_NEAR(m.structured_share_after(0.8, 0.0, 0.01), 0.8 * std::exp(-0.2), 1e-15);
  EXPECT_NEAR(m.structured_share_after(0.8, 0.5, 0.01), 0.8 * std::exp(-0.4), 1e-15);
  EXPECT_EQ(m.structured_share_after(0.8, 0.0, -0.01), 0.8);
  m.fragmentation_strain = 0.1;
  EXPECT_NEAR(m.structured_share_after(1.0, 0.0, 0.01), std::exp(-0.1), 1e-15);
  m.basal_pressure_factor = 1.5;
  EXPECT_THROW(m.check(), std::invalid_argument);
}

// A weakly cohesive mound spreads and breaks up: the fluid its blocks held
// leaves it at their rate (eq. 27), taking its own mass, and what is taken is
// exactly what the points lost.
TEST(DepthAveragedSolver, BreakingBlocksReleaseTheirConfinedFluid) {
  auto s = ground(0.0, 40, 30, 0.25);
  auto m = sand(0.0, 500.0);
  m.degradation = CohesionDegradation(0.05);
  m.confined_fluid_fraction = 0.3;
  DepthAveragedParticles p;
  p.seed(
      {3.0, 2.5}, {6.0, 5.0}, s.grid.spacing, 2,
      [](const Vec<2>& x) { return 1.5 - 0.2 * std::abs(x[0] - 4.5); }, m.density, 0);
  const double mass = p.total_mass();
  double volume = 0.0;
  for (double v : p.volume) volume += v;
  DepthAveragedSolver solver(s, {m}, p);
  EXPECT_NEAR(std::accumulate(solver.particles().confined_fluid.begin(),
                              solver.particles().confined_fluid.end(), 0.0),
              0.3 * volume, 1e-12 * volume);
  double released = 0.0;
  for (int k = 0; k < 20; ++k) {
    solver.advance_to(0.05 * (k + 1));
    for (double v : solver.take_released_fluid()) released += v;
  }
  const auto& q = solver.particles();
  const double volume_left = std::accumulate(q.volume.begin(), q.volume.end(), 0.0);
  const double confined_left =
      std::accumulate(q.confined_fluid.begin(), q.confined_fluid.end(), 0.0);
  EXPECT_GT(released, 0.01 * volume);  // it did break up
  EXPECT_NEAR(volume_left + released, volume, 1e-12 * volume);
  EXPECT_NEAR(q.total_mass() + s.confined_fluid_density * released, mass, 1e-12 * mass);
  EXPECT_NEAR(confined_left + released, 0.3 * volume, 1e-12 * volume);
  // Fluid and blocks went at one rate: C = 0.3 f_sc V0 with V = V0 - 0.3 V0 (1 - f_sc).
  for (std::size_t i = 0; i < q.size(); ++i) {
    const double share = q.structured_share[i];
    EXPECT_NEAR(q.confined_fluid[i], 0.3 * share * q.volume[i] / (1.0 - 0.3 * (1.0 - share)),
                1e-12 * q.volume[i]);
  }
  const std::vector<double> none = solver.take_released_fluid();
  EXPECT_TRUE(std::all_of(none.begin(), none.end(), [](double v) { return v == 0.0; }));
}

TEST(DepthAveragedSolver, AnImpulseChangesEachPointsVelocityByItOverItsMass) {
  const auto s = ground(0.0, 8, 6, 0.5);
  auto solver = block(s, sand(0.0), {1.0, 1.0}, {2.0, 2.0}, 0.5);
  const auto& q = solver.particles();
  std::vector<Vec<2>> impulse(q.size());
  for (std::size_t p = 0; p < q.size(); ++p) impulse[p] = Vec<2>{2.0, -1.0} * q.mass[p];
  solver.apply_impulse(impulse);
  for (const auto& v : q.velocity) EXPECT_NEAR((v - Vec<2>{2.0, -1.0}).norm(), 0.0, 1e-15);
  impulse.pop_back();
  EXPECT_THROW(solver.apply_impulse(impulse), std::invalid_argument);
}

// Only the thrust acts (level ground, no friction, the walls not reached):
// P2G, the grid update, the PIC/FLIP transfer and the splitting of stretched
// points conserve momentum, and the mass is the points'.
TEST(DepthAveragedSolver, ASpreadingMoundKeepsItsMassAndMomentumToRoundOff) {
  auto s = ground(0.0, 40, 30, 0.25);
  DepthAveragedParticles p;
  p.seed(
      {2.0, 2.0}, {6.0, 5.0}, s.grid.spacing, 3,
      [](const Vec<2>& x) { return 1.0 + 0.3 * std::sin(x[0]) * std::cos(2.0 * x[1]); }, 1800.0, 0);
  const double mass = p.total_mass();
  DepthAveragedSolver solver(s, {sand(0.0)}, p);
  solver.advance_to(0.15);
  const double scale = mass * std::sqrt(g * 1.3);
  EXPECT_NEAR(solver.particles().total_mass(), mass, 1e-12 * mass);
  EXPECT_LT(solver.particles().momentum().norm(), 1e-12 * scale)
      << solver.particles().momentum().transpose();
  double fastest = 0.0;
  for (const auto& v : solver.particles().velocity) fastest = std::max(fastest, v.norm());
  EXPECT_GT(fastest, 0.5);  // it did spread
}

// tan(delta) above the slope: friction holds the block exactly where it is.
TEST(DepthAveragedSolver, FrictionHoldsABlockOnASlopeFlatterThanItsFrictionAngle) {
  const auto s = ground(20.0, 20, 6, 0.5);
  auto m = sand(25.0, 1.0e6);  // cohesive: no thrust, the block is rigid
  auto solver = block(s, m, {3.0, 1.0}, {6.0, 2.0}, 0.5);
  const Vec<2> start = solver.particles().centre_of_mass();
  for (int k = 0; k < 200; ++k) solver.step(5e-3);
  EXPECT_EQ((solver.particles().centre_of_mass() - start).norm(), 0.0);
}

// Thrown up the slope, the block decelerates at g (sin + cos tan(delta)),
// stops, and friction never pushes it back down.
TEST(DepthAveragedSolver, FrictionStopsAMassButNeverReversesIt) {
  const double theta = 15.0 * deg, delta = 25.0 * deg, v0 = 2.0;
  const auto s = ground(15.0, 40, 6, 0.5);
  auto solver = block(s, sand(25.0, 1.0e6), {12.0, 1.0}, {14.0, 2.0}, 0.5, {-v0, 0.0});
  const double x0 = solver.particles().centre_of_mass()[0];
  const double decel = g * (std::sin(theta) + std::cos(theta) * std::tan(delta));
  const double stop_time = v0 / decel;
  const double dt = 1e-3;
  while (solver.time() < 0.5 * stop_time) solver.step(dt);
  EXPECT_NEAR(solver.particles().momentum()[0] / solver.particles().total_mass(),
              -v0 + decel * solver.time(), 1e-9);
  while (solver.time() < 2.0 * stop_time) solver.step(dt);
  const double travelled = solver.particles().centre_of_mass()[0] - x0;
  EXPECT_NEAR(travelled, -v0 * v0 / (2.0 * decel), 2.0 * v0 * dt);
  for (const auto& v : solver.particles().velocity) EXPECT_EQ(v.norm(), 0.0);
  for (int k = 0; k < 100; ++k) solver.step(dt);
  EXPECT_EQ(solver.particles().centre_of_mass()[0] - x0, travelled);
}

// The walls hold the mass on the grid at stable steps; a step far beyond
// them carries it off, which stops the run.
TEST(DepthAveragedSolver, APointLeavingTheGridStopsTheRunWithANumericalError) {
  const auto s = ground(30.0, 8, 4, 0.5);
  auto solver = block(s, sand(0.0, 1.0e6), {1.5, 0.5}, {2.5, 1.5}, 0.3, {20.0, 0.0});
  EXPECT_THROW(solver.step(1.0), cosim::NumericalError);
}

TEST(DepthAveragedSolver, RefusesPointsOutsideTheGridAndBadSettings) {
  const auto s = ground(0.0, 4, 4, 1.0);
  DepthAveragedParticles p;
  p.add({5.0, 1.0}, Vec<2>::Zero(), 1.0, 1.0, 1000.0, 0);
  EXPECT_THROW(DepthAveragedSolver(s, {sand(10.0)}, p), std::invalid_argument);
  DepthAveragedParticles q;
  q.add({1.0, 1.0}, Vec<2>::Zero(), 1.0, 1.0, 1000.0, 1);
  EXPECT_THROW(DepthAveragedSolver(s, {sand(10.0)}, q), std::invalid_argument);
  auto bad = s;
  bad.flip_fraction = 1.5;
  EXPECT_THROW(DepthAveragedSolver(bad, {sand(10.0)}, DepthAveragedParticles{}),
               std::invalid_argument);
  auto wet = sand(10.0);
  wet.density = -1.0;
  EXPECT_THROW(DepthAveragedSolver(s, {wet}, DepthAveragedParticles{}), std::invalid_argument);
}

}  // namespace
}  // namespace mpm
