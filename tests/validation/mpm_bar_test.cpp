// mpm-bar: axial vibration of an elastic bar, fixed at x = 0 and free at
// x = L (configs/mpm/validation/elastic_bar_vibration.yaml). Plane strain
// with nu = 0: the constrained modulus is E, so c = sqrt(E / rho) and the
// first mode v(x, t) = v0 sin(pi x / 2L) cos(omega t) has the period
// T = 2 pi / omega = 4 L / c. The centre-of-mass velocity follows cos(omega t);
// its zero crossings over 10 periods give the measured period. The
// energy (kinetic + strain, Solver::totals) must stay within 1 % of its
// initial value over the same time.
//
// CI runs 0.5 m cells (50 across the bar); COSIM_FULL_VALIDATION the case
// file's 0.25 m cells. The GIMP period error halves with the cell size
// (1.27 % at 1 m, 0.62 % at 0.5 m, 0.30 % at 0.25 m: first order), while
// linear and quadratic B-spline shapes converge at second order.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "mpm/case/load_case.hpp"
#include "mpm/solver/solver.hpp"
#include "mpm_case_resolution.hpp"

namespace mpm {
namespace {

const std::string case_file = COSIM_SOURCE_DIR "/configs/mpm/validation/elastic_bar_vibration.yaml";

constexpr double youngs_modulus = 100.0;  // [Pa]
constexpr double density = 1.0;           // [kg/m^3]
constexpr double length = 25.0;           // L [m]
constexpr double periods = 10.0;

#ifdef COSIM_FULL_VALIDATION
constexpr int coarsening = 1;
#else
constexpr int coarsening = 2;
#endif

struct BarResult {
  double period = 0.0;
  double energy_drift = 0.0;  // max |E(t) - E(0)| / E(0)
  double wall_seconds = 0.0;
};

BarResult vibrate(ShapeKind shape) {
  const auto start = std::chrono::steady_clock::now();
  CaseDescription description = validation::load_case_scaled(case_file, 1.0 / coarsening);
  description.threads =
      1;  // OpenMP teams spin-wait: on a shared, loaded CI machine one thread is faster
  description.shape = shape;
  const double wave_speed = std::sqrt(youngs_modulus / density);
  const double period = 4.0 * length / wave_speed;
  description.time.end_time = periods * period;
  Solver<2> solver(description);

  // First mode, small amplitude: v0 = 1e-3 c.
  const double v0 = 1e-3 * wave_speed;
  auto& particles = solver.particles();
  for (std::size_t p = 0; p < particles.size(); ++p)
    particles.velocity[p] =
        Vec<2>(v0 * std::sin(std::numbers::pi * particles.position[p].x() / (2.0 * length)), 0.0);

  const auto energy = [&] {
    const Totals<2> t = solver.totals();
    return t.kinetic_energy + t.strain_energy;
  };
  const auto centre_velocity = [&] {
    const Totals<2> t = solver.totals();
    return t.momentum.x() / t.mass;
  };
  const double initial_energy = energy();
  double drift = 0.0;
  std::vector<double> crossings;
  double last_time = 0.0;
  double last_velocity = centre_velocity();
  while (solver.time() < description.time.end_time) {
    const double dt =
        std::min(solver.stable_time_step(), description.time.end_time - solver.time());
    solver.step(dt);
    const double v = centre_velocity();
    if ((last_velocity > 0.0) != (v > 0.0))
      crossings.push_back(last_time + dt * last_velocity / (last_velocity - v));
    last_time = solver.time();
    last_velocity = v;
    drift = std::max(drift, std::abs(energy() - initial_energy) / initial_energy);
  }
  solver.check_state();
  BarResult result;
  if (crossings.size() >= 2)
    result.period =
        2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  result.energy_drift = drift;
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void check_bar(ShapeKind shape, bool assert_tolerances) {
  const double period = 4.0 * length / std::sqrt(youngs_modulus / density);
  const BarResult r = vibrate(shape);
  const double period_error = std::abs(r.period - period) / period;
  fmt::print(
      "mpm-bar {} ({} m cells): period {:.5f} s vs T = 4L/c = {:.5f} s, error {:.3f} % (tolerance "
      "1 %); "
      "energy drift {:.3f} % (tolerance 1 %); wall {:.1f} s\n",
      to_string(shape), 0.25 * coarsening, r.period, period, 100.0 * period_error,
      100.0 * r.energy_drift, r.wall_seconds);
  if (!assert_tolerances) return;
  EXPECT_LT(period_error, 0.01);
  EXPECT_LT(r.energy_drift, 0.01);
}

TEST(MpmBarValidation, GimpPeriodAndEnergy) {
  check_bar(ShapeKind::gimp, true);
}

TEST(MpmBarValidation, QuadraticBsplinePeriodAndEnergy) {
  check_bar(ShapeKind::quadratic_bspline, true);
}

TEST(MpmBarValidation, LinearPeriodAndEnergy) {
  check_bar(ShapeKind::linear, true);
}

}  // namespace
}  // namespace mpm
