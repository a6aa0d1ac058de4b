// Masses sliding down an inclined plane, against their exact motion:
//  - a Savage-Hutter parabolic cap (Hutter et al. 1993): whatever its
//    spreading, while all of it moves downslope its centre of mass
//    accelerates at g (sin(zeta) - cos(zeta) tan(delta));
//  - a block whose cohesion keeps its whole depth above the crack depth
//    slides rigidly, x = g (sin(theta) - cos(theta) tan(delta)) t^2 / 2, and
//    takes no damage; with little cohesion the same block yields, spreads,
//    and its bonds break (van den Bout et al., OpenLISEM Hazard, eq. 26);
//  - the cohesive block deep in a lake slides rigidly at
//    g ((1 - gamma) sin(theta) - (1 - B gamma) cos(theta) tan(delta)),
//    gamma = rho_f / rho: buoyancy always, and the fluid's pressure at its
//    base as far as the basal pressure factor B lets it through (eq. 39).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "mpm/depth_averaged/depth_averaged_solver.hpp"

namespace mpm {
namespace {

constexpr double deg = std::numbers::pi / 180.0;
constexpr double g = 9.81;

DepthAveragedMaterial material(double delta_deg, double cohesion, double critical_strain) {
  DepthAveragedMaterial m;
  m.name = "soil";
  m.density = 2000.0;
  m.internal_friction_angle = 30.0 * deg;
  m.basal_friction_angle = delta_deg * deg;
  m.cohesion = cohesion;
  if (critical_strain > 0.0) m.degradation = CohesionDegradation(critical_strain);
  return m;
}

DepthAveragedSettings plane(double theta_deg, Vec<2> origin, std::array<int, 2> cells, double dx,
                            EarthPressureModel model) {
  DepthAveragedSettings s;
  s.grid.origin = origin;
  s.grid.spacing = Vec<2>::Constant(dx);
  s.grid.cells = cells;
  s.terrain = Terrain(theta_deg * deg, g);
  s.earth_pressure = EarthPressure(model);
  return s;
}

TEST(SavageHutterCap, ItsCentreOfMassAcceleratesAtGravityLessFriction) {
  const double zeta = 35.0 * deg, delta = 20.0 * deg, h0 = 1.0, L = 10.0, dx = 0.5, t = 4.0;
  const auto s = plane(35.0, {-30.0, 0.0}, {200, 2}, dx, EarthPressureModel::isotropic);
  const auto m = material(20.0, 0.0, 0.0);
  DepthAveragedParticles points;
  points.seed(
      {-L, 0.0}, {L, 2.0 * dx}, s.grid.spacing, 3,
      [&](const Vec<2>& x) { return h0 * (1.0 - (x[0] / L) * (x[0] / L)); }, m.density, 0);
  DepthAveragedSolver solver(s, {m}, points);
  const double x0 = solver.particles().centre_of_mass()[0];
  double slowest = 1e300;
  while (solver.time() < t) {
    solver.step(std::min(solver.stable_time_step(), t - solver.time()));
    for (const auto& v : solver.particles().velocity) slowest = std::min(slowest, v[0]);
  }
  const double a = g * (std::sin(zeta) - std::cos(zeta) * std::tan(delta));
  const double moved = solver.particles().centre_of_mass()[0] - x0;
  const double speed = solver.particles().momentum()[0] / solver.particles().total_mass();
  double back = 1e300, front = -1e300;
  for (const auto& x : solver.particles().position) {
    back = std::min(back, x[0]);
    front = std::max(front, x[0]);
  }
  const double position_error = (moved - 0.5 * a * t * t) / (0.5 * a * t * t);
  const double speed_error = (speed - a * t) / (a * t);
  fmt::print(
      "Savage-Hutter cap at {} s: centre moved {:.4f} m, exact {:.4f} m ({:+.2e}, tolerance "
      "2 %); speed {:.4f} m/s, exact {:.4f} ({:+.2e}, tolerance 2 %); spread from {} m to {:.2f} "
      "m; slowest point {:.3f} m/s\n",
      t, moved, 0.5 * a * t * t, position_error, speed, a * t, speed_error, 2.0 * L, front - back,
      slowest);
  EXPECT_GT(slowest, 0.0);           // the premise: all of it moves downslope
  EXPECT_GT(front - back, 2.2 * L);  // and it spread
  EXPECT_LT(std::abs(position_error), 0.02);
  EXPECT_LT(std::abs(speed_error), 0.02);
}

struct BlockRun {
  double moved = 0.0, length = 0.0, initial_length = 0.0, width = 0.0, max_damage = 0.0;
};

BlockRun slide_block(double cohesion, double t, double theta_deg = 30.0, double delta_deg = 20.0,
                     std::optional<StillWater> water = std::nullopt,
                     double basal_pressure_factor = 1.0) {
  auto s = plane(theta_deg, {0.0, 0.0}, {120, 40}, 0.25, EarthPressureModel::rankine);
  s.still_water = water;
  auto m = material(delta_deg, cohesion, 0.01);
  m.basal_pressure_factor = basal_pressure_factor;
  DepthAveragedParticles points;
  points.seed(
      {2.0, 4.0}, {6.0, 6.0}, s.grid.spacing, 2, [](const Vec<2>&) { return 1.0; }, m.density, 0);
  DepthAveragedSolver solver(s, {m}, points);
  const auto extent = [&](int d) {
    double lo = 1e300, hi = -1e300;
    for (const auto& x : solver.particles().position) {
      lo = std::min(lo, x[d]);
      hi = std::max(hi, x[d]);
    }
    return hi - lo;
  };
  BlockRun r;
  r.initial_length = extent(0);
  const double x0 = solver.particles().centre_of_mass()[0];
  solver.advance_to(t);
  r.moved = solver.particles().centre_of_mass()[0] - x0;
  r.length = extent(0);
  r.width = extent(1);
  for (double d : solver.particles().damage) r.max_damage = std::max(r.max_damage, d);
  return r;
}

TEST(BlockOnSlope, ACohesiveBlockSlidesRigidlyAndALooseOneSpreadsAndBreaks) {
  const double theta = 30.0 * deg, delta = 20.0 * deg, t = 3.0;
  const double exact = 0.5 * g * (std::sin(theta) - std::cos(theta) * std::tan(delta)) * t * t;
  const BlockRun strong = slide_block(100.0e3, t);  // crack depth 20 m: no yield in 1 m
  const BlockRun weak = slide_block(2.0e3, t);      // crack depth 0.2 m
  const double error = (strong.moved - exact) / exact;
  fmt::print(
      "Block on a 30 deg slope, delta 20 deg, after {} s:\n"
      "  c = 100 kPa: moved {:.4f} m, exact {:.4f} m ({:+.2e}, tolerance 2 %), length {:.4f} -> "
      "{:.4f} m, largest damage {}\n"
      "  c = 2 kPa: moved {:.4f} m, length {:.3f} -> {:.3f} m, width 2 -> {:.3f} m, largest "
      "damage {:.3f}\n",
      t, strong.moved, exact, error, strong.initial_length, strong.length, strong.max_damage,
      weak.moved, weak.initial_length, weak.length, weak.width, weak.max_damage);
  EXPECT_LT(std::abs(error), 0.02);
  EXPECT_NEAR(strong.length, strong.initial_length, 1e-9);
  EXPECT_EQ(strong.max_damage, 0.0);
  EXPECT_GT(weak.length, 1.2 * weak.initial_length);
  EXPECT_GT(weak.max_damage, 0.5);
}

TEST(SubmergedBlock, SlidesAtTheBuoyedAccelerationThatTheBasalPressureFactorSets) {
  const double theta = 40.0 * deg, delta = 15.0 * deg, t = 3.0, gamma = 1000.0 / 2000.0;
  const StillWater lake{1000.0, 100.0};  // far above the block all the way
  for (const double B : {1.0, 0.0}) {
    const double acceleration =
        g * ((1 - gamma) * std::sin(theta) - (1 - B * gamma) * std::cos(theta) * std::tan(delta));
    const double exact = 0.5 * acceleration * t * t;
    const BlockRun run = slide_block(100.0e3, t, 40.0, 15.0, lake, B);
    const double error = (run.moved - exact) / exact;
    fmt::print(
        "Block deep in a lake on a 40 deg slope, delta 15 deg, B = {}: moved {:.4f} m in {} s, "
        "exact {:.4f} m ({:+.2e}, tolerance 2 %); dry it would move {:.4f} m\n",
        B, run.moved, t, exact, error,
        0.5 * g * (std::sin(theta) - std::cos(theta) * std::tan(delta)) * t * t);
    EXPECT_LT(std::abs(error), 0.02) << "B = " << B;
    EXPECT_NEAR(run.length, run.initial_length, 1e-9);
    EXPECT_EQ(run.max_damage, 0.0);
  }
}

}  // namespace
}  // namespace mpm
