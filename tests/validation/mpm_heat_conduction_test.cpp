// mpm-heat-bar: transient conduction along a bar held at two temperatures
// (configs/mpm/validation/heat_conduction_bar.yaml) against the Fourier
// series of the file's header, at the file's resolution (40 cells, GIMP):
// every particle's temperature at 1000 s and at the end (10000 s), and the
// thermal balance of Solver::totals.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "mpm/case/load_case.hpp"
#include "mpm/solver/solver.hpp"

namespace mpm {
namespace {

const std::string case_file = COSIM_SOURCE_DIR "/configs/mpm/validation/heat_conduction_bar.yaml";

constexpr double pi = std::numbers::pi;
constexpr double length = 0.2;                          // L [m]
constexpr double diffusivity = 2.5 / (2300.0 * 900.0);  // k / (rho c) [m^2/s]
constexpr double T0 = 293.15, T_left = 373.15, T_right = 293.15;

double series(double x, double t) {
  double T = T_left + (T_right - T_left) * x / length;
  for (int n = 1; n <= 400; ++n) {
    const double sign = n % 2 == 0 ? 1.0 : -1.0;
    const double b = 2.0 / (n * pi) * ((T0 - T_left) * (1.0 - sign) + (T_right - T_left) * sign);
    T += b * std::sin(n * pi * x / length) *
         std::exp(-diffusivity * std::pow(n * pi / length, 2) * t);
  }
  return T;
}

TEST(MpmHeatConductionBar, FollowsTheFourierSeries) {
  const CaseDescription description = load_case(case_file);
  ASSERT_TRUE(description.thermal.enabled);
  Solver<2> solver(description);
  const double energy = solver.totals().thermal_energy;
  for (const double t : {1000.0, description.time.end_time}) {
    while (solver.time() < t - 1e-9)
      solver.step(std::min(solver.stable_time_step(), t - solver.time()));
    double error = 0.0;
    const auto& p = solver.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      error = std::max(error, std::abs(p.temperature[i] - series(p.position[i][0], t)));
    error /= T_left - T0;
    fmt::print("  t = {:5.0f} s ({} steps): max |T - T_series| = {:.2e} of dT (tolerance 2e-3)\n",
               t, solver.step_count(), error);
    EXPECT_LT(error, 2e-3);
  }
  const Totals<2> totals = solver.totals();
  const double balance =
      std::abs(totals.thermal_energy - energy - totals.heat_through_faces) / energy;
  fmt::print(
      "  thermal energy {:.9g} -> {:.9g} J/m, {:.6g} J/m in through the faces: balance {:.1e} "
      "(tolerance 1e-12)\n",
      energy, totals.thermal_energy, totals.heat_through_faces, balance);
  EXPECT_LT(balance, 1e-12);
  EXPECT_GT(totals.heat_through_faces, 0.0);
}

}  // namespace
}  // namespace mpm
