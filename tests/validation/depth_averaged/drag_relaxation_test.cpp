// The drag between the solid and fluid phases of a depth-averaged debris
// mixture in one cell with no other force (van den Bout et al., OpenLISEM
// Hazard 2.0a, eqs. 50-53 reduced to 0-D), against its exact solution:
//   linear drag (j = 1):    du(t) = du0 exp(-K (1/(a_s r_s) + 1/(a_f r_f)) t),
//   quadratic drag (j = 2): |du(t)| = |du0| / (1 + K mu |du0| t),
// both slowed by 1 + V mu with a virtual mass V (eq. 65). K is Pudasaini's
// generalised coefficient (eqs. 61-64) of a sand-water mixture with a fixed
// smoothing speed, constant in time. The exact time integration must meet
// the solution within 1e-6 at any step, including dt K mu = 1e3, and keep
// the momentum to round-off. With the smoothing speed read from the
// velocities (eq. 63) the coefficient changes as the phases relax; that run
// is checked for monotone decay and for the momentum of every step, and the
// error of lagging the coefficient by a step is printed.

#include "cosim/exchange/drag_relaxation.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "cosim/exchange/generalised_drag.hpp"

namespace cosim::exchange {
namespace {

constexpr double kTolerance = 1e-6;

DebrisMixture sand_in_water() {
  return {.solid_fraction = 0.4, .solid_density = 2650, .fluid_density = 1000};
}

GeneralisedDragParameters drag_parameters(double exponent) {
  GeneralisedDragParameters parameters;
  parameters.exponent = exponent;
  parameters.grain_size = 1e-3;
  parameters.smoothing_speed = 1.0;
  return parameters;
}

struct Phases {
  std::array<double, 2> solid{0.0, 0.0};
  std::array<double, 2> fluid{2.0, -1.0};
};

DragRelaxation cell_of(const DebrisMixture& mixture, double coefficient, double exponent,
                       bool virtual_mass) {
  DragRelaxation cell;
  cell.solid_weight = mixture.confined_fraction() * mixture.confined_density();
  cell.fluid_weight = mixture.free_fluid_fraction() * mixture.fluid_density;
  cell.drag_coefficient = coefficient;
  cell.exponent = exponent;
  if (virtual_mass) {
    cell.virtual_mass =
        mixture.confined_fraction() * mixture.fluid_density * virtual_mass_coefficient(mixture);
  }
  return cell;
}

double speed(const std::array<double, 2>& v) {
  return std::hypot(v[0], v[1]);
}

std::array<double, 2> relative(const Phases& p) {
  return {p.fluid[0] - p.solid[0], p.fluid[1] - p.solid[1]};
}

std::array<double, 2> momentum(const DragRelaxation& cell, const Phases& p) {
  return {cell.solid_weight * p.solid[0] + cell.fluid_weight * p.fluid[0],
          cell.solid_weight * p.solid[1] + cell.fluid_weight * p.fluid[1]};
}

struct Case {
  const char* name;
  double exponent;
  bool virtual_mass;
  double steps_per_time_scale;  // 1 / (dt K mu |du0|^(j-1))
};

class ExactDragRelaxation : public ::testing::TestWithParam<Case> {};

TEST_P(ExactDragRelaxation, MatchesTheExactSolutionAtAnyStepAndKeepsTheMomentum) {
  const Case c = GetParam();
  const DebrisMixture mixture = sand_in_water();
  const GeneralisedDragParameters parameters = drag_parameters(c.exponent);
  Phases phases;
  const std::array<double, 2> at_rest{0.0, 0.0};
  const double coefficient = generalised_drag_coefficient(mixture, parameters, at_rest, at_rest);
  const DragRelaxation cell = cell_of(mixture, coefficient, c.exponent, c.virtual_mass);
  const double mu = 1 / cell.solid_weight + 1 / cell.fluid_weight;
  const double rate = coefficient * mu / (1 + cell.virtual_mass * mu);
  const std::array<double, 2> du0 = relative(phases);
  const double w0 = speed(du0);
  const double time_scale = 1 / (rate * std::pow(w0, c.exponent - 1));
  const double dt = time_scale / c.steps_per_time_scale;
  const std::array<double, 2> p0 = momentum(cell, phases);
  const double momentum_scale =
      cell.solid_weight * speed(phases.solid) + cell.fluid_weight * speed(phases.fluid);

  double worst_error = 0;  // |du - exact| / max(|exact|, 1e-300 w0) over the run
  double worst_absolute = 0;
  double worst_momentum = 0;
  double backward_euler = w0;  // for comparison: ICE's exchange, 1 / (1 + a dt) per step
  double t = 0;
  const int steps = std::max(3, static_cast<int>(std::ceil(5 * c.steps_per_time_scale)));
  for (int n = 0; n < steps; ++n) {
    relax_drag(cell, dt, phases.solid, phases.fluid);
    t += dt;
    backward_euler /= 1 + rate * std::pow(backward_euler, c.exponent - 1) * dt;
    const double exact_ratio = c.exponent == 1 ? std::exp(-rate * t) : 1 / (1 + rate * w0 * t);
    const std::array<double, 2> du = relative(phases);
    for (int k = 0; k < 2; ++k) {
      const double exact = du0[k] * exact_ratio;
      const double error = std::abs(du[k] - exact);
      worst_absolute = std::max(worst_absolute, error / w0);
      if (std::abs(exact) > 1e-12 * w0) {
        worst_error = std::max(worst_error, error / std::abs(exact));
      }
    }
    const std::array<double, 2> p = momentum(cell, phases);
    worst_momentum = std::max({worst_momentum, std::abs(p[0] - p0[0]) / momentum_scale,
                               std::abs(p[1] - p0[1]) / momentum_scale});
  }
  const double exact_end = c.exponent == 1 ? std::exp(-rate * t) : 1 / (1 + rate * w0 * t);
  fmt::print(
      "drag relaxation j={} virtual mass {}: K = {:.4g}, dt K mu |du0|^(j-1) = {:.3g}, "
      "{} steps to t = {:.3g} s: worst relative error {:.2e} (absolute {:.2e} of |du0|; "
      "tolerance {:.0e}); momentum {:.1e} (tolerance 1e-14){}\n",
      c.exponent, c.virtual_mass ? "on" : "off", coefficient, 1 / c.steps_per_time_scale, steps, t,
      worst_error, worst_absolute, kTolerance, worst_momentum,
      c.exponent == 1 ? fmt::format("; backward Euler would leave {:.4g} of |du0| where the "
                                    "exact is {:.4g}",
                                    backward_euler / w0, exact_end)
                      : std::string("; backward Euler with the lagged |du| is exact for j = 2"));
  EXPECT_LE(worst_error, kTolerance);
  EXPECT_LE(worst_absolute, kTolerance);
  EXPECT_LE(worst_momentum, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(
    LinearAndQuadraticDrag, ExactDragRelaxation,
    ::testing::Values(Case{"LinearFineSteps", 1, false, 100},
                      Case{"LinearStepOfTheTimeScale", 1, false, 1},
                      Case{"LinearStepOfAThousandTimeScales", 1, false, 1e-3},
                      Case{"LinearWithVirtualMass", 1, true, 1},
                      Case{"QuadraticFineSteps", 2, false, 100},
                      Case{"QuadraticStepOfAThousandTimeScales", 2, false, 1e-3},
                      Case{"QuadraticWithVirtualMass", 2, true, 1}),
    [](const ::testing::TestParamInfo<Case>& param) { return std::string(param.param.name); });

TEST(DragRelaxation, WithTheSmoothingSpeedFromTheVelocitiesStaysMonotoneAndConservative) {
  const DebrisMixture mixture = sand_in_water();
  GeneralisedDragParameters parameters = drag_parameters(1);
  parameters.smoothing_speed.reset();
  const double end = 0.05;
  auto run = [&](double dt, double& worst_momentum, bool& monotone) {
    Phases phases;
    const DragRelaxation reference = cell_of(mixture, 0, 1, false);
    const double scale = reference.fluid_weight * speed(phases.fluid);
    double previous = speed(relative(phases));
    worst_momentum = 0;
    monotone = true;
    for (double t = 0; t < end - 1e-15; t += dt) {
      const double k =
          generalised_drag_coefficient(mixture, parameters, phases.solid, phases.fluid);
      const std::array<double, 2> before = momentum(reference, phases);
      relax_drag(cell_of(mixture, k, 1, false), std::min(dt, end - t), phases.solid, phases.fluid);
      const std::array<double, 2> p = momentum(reference, phases);
      worst_momentum = std::max(
          {worst_momentum, std::abs(p[0] - before[0]) / scale, std::abs(p[1] - before[1]) / scale});
      const double now = speed(relative(phases));
      monotone = monotone && now <= previous && relative(phases)[0] * 2.0 >= 0;
      previous = now;
    }
    return speed(relative(phases));
  };
  double momentum_fine = 0, momentum_coarse = 0;
  bool monotone_fine = true, monotone_coarse = true;
  const double fine = run(1e-6, momentum_fine, monotone_fine);
  const double coarse = run(end, momentum_coarse, monotone_coarse);
  const double medium = run(end / 100, momentum_coarse, monotone_coarse);
  fmt::print(
      "drag relaxation, smoothing speed from the velocities (eq. 63): |du| at {} s = {:.6g} "
      "(dt 1e-6 s), {:.6g} (dt {} s, one step), {:.6g} (dt {} s): the lag of the coefficient "
      "costs {:.2e} and {:.2e} of |du0|\n",
      end, fine, coarse, end, medium, end / 100, std::abs(coarse - fine) / std::sqrt(5.0),
      std::abs(medium - fine) / std::sqrt(5.0));
  EXPECT_TRUE(monotone_fine);
  EXPECT_TRUE(monotone_coarse);
  fmt::print("largest change of the momentum in one step: {:.1e} (tolerance 1e-15)\n",
             std::max(momentum_fine, momentum_coarse));
  EXPECT_LE(std::max(momentum_fine, momentum_coarse), 1e-15);
}

}  // namespace
}  // namespace cosim::exchange
