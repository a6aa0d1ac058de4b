// A block across a break in slope (van den Bout et al., OpenLISEM Hazard:
// "block on a slope, high vs low cohesion"): its rear half rests on a bed
// falling at 0.3, flatter than its friction (tan 25 deg = 0.466), its front
// half on one falling at 0.8. Held together by its in-plane stress (eq. 43's
// last term), a cohesive block slides as one body, x'' = g (the mean bed
// slope under it - tan(delta)), the front pulling the rear with a tension of
// about 10 kPa; a weak block (2 kPa) cannot carry it, tears at the break and
// its front runs away from its rear, which stays where it was. Without the
// in-plane stress (E = 0, the earth pressure alone) nothing holds the strong
// block together either.
// The strong block is stiff (E = 500 MPa): until its stress wave has crossed
// it (L / c = 0.008 s) its rear stands still under static friction, which is
// less than the sliding friction of the rigid body, so a softer block gets
// ahead of the rigid one: +3.0 % at 1 s with E = 50 MPa, +1.0 % with 500 MPa.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mpm/depth_averaged/depth_averaged_solver.hpp"

namespace mpm {
namespace {

constexpr double deg = std::numbers::pi / 180.0;
constexpr double g = 9.81;

struct BlockAcrossBreak {
  double rear_moved = 0.0, front_moved = 0.0, neck_depth = 0.0, max_damage = 0.0;
  double initial_centre = 0.0, centre = 0.0;
  double rigid = 0.0;  // how far the same points would move as a rigid body [m]
};

double bed_slope(double x) {
  return x < 6.0 ? 0.3 : 0.8;
}

// A rigid body of the given points sliding over the bed: x'' = g (mean slope
// under its points - tan(delta)), integrated with small steps (RK2).
double rigid_displacement(const std::vector<Vec<2>>& start, double tan_delta, double t) {
  auto acceleration = [&](double x) {
    double slope = 0.0;
    for (const auto& p : start) slope += bed_slope(p[0] + x);
    return g * (slope / static_cast<double>(start.size()) - tan_delta);
  };
  double x = 0.0, v = 0.0;
  const int steps = 20000;
  const double dt = t / steps;
  for (int k = 0; k < steps; ++k) {
    const double a1 = acceleration(x);
    const double a2 = acceleration(x + dt * v + 0.5 * dt * dt * a1);
    x += dt * v + 0.5 * dt * dt * a1;
    v += 0.5 * dt * (a1 + a2);
  }
  return x;
}

BlockAcrossBreak slide(double cohesion, double youngs_modulus, double t) {
  // Bed: 10 - 0.3 x for x < 6 m, then falling at 0.8; raster at 0.25 m.
  const double dx = 0.25;
  std::vector<double> bed;
  const int columns = 161, rows = 17;
  for (int row = 0; row < rows; ++row)
    for (int column = 0; column < columns; ++column) {
      const double x = column * dx;
      bed.push_back(x < 6.0 ? 10.0 - 0.3 * x : 10.0 - 1.8 - 0.8 * (x - 6.0));
    }
  DepthAveragedSettings s;
  s.grid.origin = Vec<2>::Zero();
  s.grid.spacing = Vec<2>::Constant(dx);
  s.grid.cells = {160, 16};
  s.terrain = Terrain(0.0, g, RasterGrid(columns, rows, Vec<2>::Zero(), dx, bed));
  s.earth_pressure = EarthPressure(EarthPressureModel::rankine);
  DepthAveragedMaterial m;
  m.name = "clay";
  m.density = 2000.0;
  m.internal_friction_angle = 30.0 * deg;
  m.basal_friction_angle = 25.0 * deg;
  m.cohesion = cohesion;
  m.degradation = CohesionDegradation(0.01);
  m.in_plane.youngs_modulus = youngs_modulus;
  m.in_plane.poisson_ratio = 0.3;
  DepthAveragedParticles points;
  points.seed(
      {3.0, 1.0}, {9.0, 3.0}, s.grid.spacing, 2, [](const Vec<2>&) { return 1.0; }, m.density, 0);
  const std::vector<Vec<2>> start = points.position;
  DepthAveragedSolver solver(s, {m}, points);
  BlockAcrossBreak r;
  r.initial_centre = solver.particles().centre_of_mass()[0];
  r.rigid = rigid_displacement(start, std::tan(m.basal_friction_angle), t);
  solver.advance_to(t);
  const auto& q = solver.particles();
  r.centre = q.centre_of_mass()[0];
  // The original points (splitting appends) that started behind and ahead of the break.
  double rear = 0.0, front = 0.0;
  int n_rear = 0, n_front = 0;
  for (std::size_t p = 0; p < start.size(); ++p) {
    const double moved = q.position[p][0] - start[p][0];
    if (start[p][0] < 5.0) {
      rear += moved;
      ++n_rear;
    } else if (start[p][0] > 7.0) {
      front += moved;
      ++n_front;
    }
  }
  r.rear_moved = rear / n_rear;
  r.front_moved = front / n_front;
  // The thinnest depth along the block's axis between its rear and front
  // parts (where it tears).
  r.neck_depth = 1e300;
  for (double x = 5.0 + r.rear_moved; x <= 7.0 + r.front_moved; x += 0.05)
    r.neck_depth = std::min(r.neck_depth, solver.depth_at({x, 2.0}));
  for (double d : q.damage) r.max_damage = std::max(r.max_damage, d);
  return r;
}

TEST(BlockAcrossSlopeBreak, ACohesiveBlockSlidesAsOneAndAWeakOneTears) {
  const double t = 1.0;
  const BlockAcrossBreak strong = slide(100.0e3, 5.0e8, t);
  const BlockAcrossBreak weak = slide(2.0e3, 5.0e7, t);
  const BlockAcrossBreak loose = slide(100.0e3, 0.0, t);
  const double exact = strong.rigid;
  const double error = (strong.centre - strong.initial_centre - exact) / exact;
  auto line = [](const char* what, const BlockAcrossBreak& r) {
    fmt::print(
        "  {}: rear moved {:.3f} m, front {:.3f} m, thinnest between {:.3f} m, damage {:.2f}\n",
        what, r.rear_moved, r.front_moved, r.neck_depth, r.max_damage);
  };
  fmt::print("Block across a slope break after {} s (a rigid block moves {:.4f} m):\n", t, exact);
  line("c = 100 kPa, E = 500 MPa", strong);
  line("c = 2 kPa,   E = 50 MPa ", weak);
  line("c = 100 kPa, E = 0      ", loose);
  fmt::print(
      "  strong block's centre moved {:.4f} m ({:+.2e} of the rigid block's, tolerance 2 %)\n",
      strong.centre - strong.initial_centre, error);
  // Strong: one body, its rear dragged along, no gap, no damage.
  EXPECT_LT(std::abs(error), 0.02);
  EXPECT_NEAR(strong.rear_moved, strong.front_moved, 0.02 * strong.front_moved);
  EXPECT_GT(strong.neck_depth, 0.95);
  EXPECT_EQ(strong.max_damage, 0.0);
  // Weak: torn at the break, its rear left behind.
  EXPECT_LT(weak.rear_moved, 0.2 * weak.front_moved);
  EXPECT_LT(weak.neck_depth, 0.3);
  EXPECT_GT(weak.max_damage, 0.5);
  // Without the in-plane stress even the strong block comes apart.
  EXPECT_LT(loose.rear_moved, 0.2 * loose.front_moved);
}

}  // namespace
}  // namespace mpm
