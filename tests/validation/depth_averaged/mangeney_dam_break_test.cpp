// Mangeney et al. (2000): a dam break on an inclined plane with Coulomb
// friction, the reservoir of depth h0 behind x = 0 released at t = 0. With
// K = 1, in the frame that accelerates at m = g (sin(theta) - cos(theta)
// tan(delta)), xi = x - m t^2 / 2, the depth is Ritter's:
//
//   h = h0                                   xi <= -c0 t
//   h = (2 c0 t - xi)^2 / (9 g cos(theta) t^2)   -c0 t < xi < 2 c0 t,
//
// c0 = sqrt(g h0 cos(theta)): the front runs at 2 c0 t + m t^2 / 2, the
// tail (where the rarefaction meets the reservoir) at -c0 t + m t^2 / 2.
// theta = 22 deg, delta = 21 deg, h0 = 1 m, 15 s, as in issue 26's table,
// on a strip one mass wide between slip walls. The reservoir is long enough
// that its upslope end's own rarefaction does not reach the tail by 15 s.
//
// How the positions are read. Ritter's front is reached only by vanishing
// mass (a point starting at x0 < 0 trails it by 3 (-x0)^(1/3) (c0 t)^(2/3)),
// and his tail is a kink that any grid smooths over a few cells. So:
//  - front and tail: where the straight line through sqrt(h) over the
//    rarefaction (0.2 h0 < h < 0.8 h0; sqrt(h) is linear in x there) meets
//    0 and sqrt(h0), i.e. the characteristics 2 c0 and -c0 as the computed
//    profile carries them;
//  - the front also where the depth falls below 1 % of h0, against the exact
//    point of that depth (no fit);
//  - the whole depth profile, L1;
//  - printed only: the furthest point (a few thin points run ahead), and the
//    tail as the 0.99 h0 point (first order in the cell size: -9.1, -4.7 and
//    -2.4 % at 0.5, 0.25 and 0.125 m).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mpm/depth_averaged/depth_averaged_solver.hpp"

namespace mpm {
namespace {

constexpr double deg = std::numbers::pi / 180.0;
constexpr double g = 9.81, theta = 22.0 * deg, delta = 21.0 * deg, h0 = 1.0, t_end = 15.0;
#ifdef COSIM_FULL_VALIDATION
constexpr double dx = 0.125;
#else
constexpr double dx = 0.25;
#endif

const double c0 = std::sqrt(g * h0 * std::cos(theta));
const double m = g * (std::sin(theta) - std::cos(theta) * std::tan(delta));

double exact_depth(double x, double t) {
  const double xi = x - 0.5 * m * t * t;
  if (xi <= -c0 * t) return h0;
  if (xi >= 2.0 * c0 * t) return 0.0;
  return (2.0 * c0 * t - xi) * (2.0 * c0 * t - xi) / (9.0 * g * std::cos(theta) * t * t);
}

// Where the exact depth falls through `fraction` h0 (inside the rarefaction).
double exact_crossing(double fraction, double t) {
  return c0 * t * (2.0 - 3.0 * std::sqrt(fraction)) + 0.5 * m * t * t;
}

TEST(MangeneyDamBreak, FrontTailAndDepthFollowTheExactSolutionAt15s) {
  DepthAveragedSettings s;
  const double x_min = -200.0, x_max = 130.0, width = 2.0 * dx;
  s.grid.origin = {x_min, 0.0};
  s.grid.spacing = Vec<2>::Constant(dx);
  s.grid.cells = {static_cast<int>(std::lround((x_max - x_min) / dx)), 2};
  s.terrain = Terrain(theta, g);
  s.earth_pressure = EarthPressure(EarthPressureModel::isotropic);
  DepthAveragedMaterial mass;
  mass.name = "granular";
  mass.density = 2000.0;
  mass.internal_friction_angle = 30.0 * deg;
  mass.basal_friction_angle = delta;
  DepthAveragedParticles points;
  points.seed(
      {-120.0, 0.0}, {0.0, width}, s.grid.spacing, 3, [](const Vec<2>&) { return h0; },
      mass.density, 0);
  DepthAveragedSolver solver(s, {mass}, points);
  const long steps = solver.advance_to(t_end);

  double furthest = -1e300;
  for (const auto& x : solver.particles().position) furthest = std::max(furthest, x[0]);
  const double exact_front = 2.0 * c0 * t_end + 0.5 * m * t_end * t_end;
  const double exact_tail = -c0 * t_end + 0.5 * m * t_end * t_end;

  const auto depth = [&](double x) { return solver.depth_at({x, 0.5 * width}); };
  const double sample = 0.25 * dx;
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, n = 0.0, l1 = 0.0, l1_exact = 0.0;
  for (double x = exact_tail - 10.0; x < exact_front + 10.0; x += sample) {
    const double h = depth(x);
    l1 += std::abs(h - exact_depth(x, t_end));
    l1_exact += exact_depth(x, t_end);
    if (h > 0.2 * h0 && h < 0.8 * h0) {
      sx += x;
      sy += std::sqrt(h);
      sxx += x * x;
      sxy += x * std::sqrt(h);
      n += 1.0;
    }
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double intercept = (sy - slope * sx) / n;
  const double front = -intercept / slope;
  const double tail = (std::sqrt(h0) - intercept) / slope;
  double front_1 = std::nan("");
  for (double x = exact_front + 20.0; x > exact_tail; x -= sample)
    if (depth(x) > 0.01 * h0) {
      front_1 = x;
      break;
    }
  double tail_99 = std::nan("");
  for (double x = exact_tail - 20.0; x < exact_front; x += sample)
    if (depth(x) < 0.99 * h0) {
      tail_99 = x;
      break;
    }
  const double front_error = (front - exact_front) / exact_front;
  const double tail_error = (tail - exact_tail) / std::abs(exact_tail);
  const double front_1_error =
      (front_1 - exact_crossing(0.01, t_end)) / exact_crossing(0.01, t_end);
  const double profile_error = l1 / l1_exact;
  fmt::print(
      "Mangeney dam break, dx = {} m, {} points at the end, {} steps: at {} s\n"
      "  front (rarefaction's line) {:.3f} m, exact {:.3f} m: {:+.2f} % (tolerance 2 %)\n"
      "  tail (rarefaction's line) {:.3f} m, exact {:.3f} m: {:+.2f} % (tolerance 2 %)\n"
      "  depth 1 % of h0 at {:.3f} m, exact {:.3f} m: {:+.2f} % (tolerance 2 %)\n"
      "  depth profile L1 {:.2f} % (tolerance 5 %)\n"
      "  printed: furthest point {:.3f} m; depth 0.99 h0 at {:.3f} m, exact {:.3f} m\n",
      dx, solver.particles().size(), steps, t_end, front, exact_front, 100.0 * front_error, tail,
      exact_tail, 100.0 * tail_error, front_1, exact_crossing(0.01, t_end), 100.0 * front_1_error,
      100.0 * profile_error, furthest, tail_99, exact_crossing(0.99, t_end));
  EXPECT_LT(std::abs(front_error), 0.02);
  EXPECT_LT(std::abs(tail_error), 0.02);
  EXPECT_LT(std::abs(front_1_error), 0.02);
  EXPECT_LT(profile_error, 0.05);
}

}  // namespace
}  // namespace mpm
