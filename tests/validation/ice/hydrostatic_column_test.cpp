// Still water under air (configs/ice/hydrostatic_column.yaml): at rest to
// |u| <= 1e-6 m/s after 1000 steps and p = p_atm + rho g h to 0.1 %.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ice_validation_run.hpp"

namespace ice {
namespace {

TEST(IceHydrostatic, WaterUnderAirStaysAtRestWithHydrostaticPressure) {
  const CaseDescription c = load_case(validation::config("hydrostatic_column.yaml"));
  auto solver = make_solver<2>(c);
  for (int step = 0; step < 1000; ++step) ASSERT_TRUE(solver->advance(1e-3).accepted);
  const double g = 9.81;
  const double p_atm = 101325.0;
  const double rho_air = c.materials[1].eos->density(p_atm, 293.15);
  const double rho_water = c.materials[0].eos->density(p_atm, 293.15);
  double fastest = 0.0;
  double worst = 0.0;
  for (int cell = 0; cell < solver->grid().cell_count(); ++cell) {
    const auto k = static_cast<std::size_t>(cell);
    for (const MaterialState<2>& m : solver->state().materials) {
      fastest = std::max({fastest, std::abs(m.velocity[0][k]), std::abs(m.velocity[1][k])});
    }
    const double y = solver->grid().cell_centre(cell)[1];
    if (y < 0.5) {
      const double rho_g_h = rho_air * g * 0.5 + rho_water * g * (0.5 - y);
      worst = std::max(worst, std::abs(solver->state().pressure[k] - p_atm - rho_g_h) / rho_g_h);
    }
  }
  fmt::print(
      "hydrostatic water under air, 1000 steps of 1 ms: fastest {:.2e} m/s (tolerance 1e-6), "
      "pressure vs p_atm + rho g h {:.2e} (tolerance 1e-3)\n",
      fastest, worst);
  EXPECT_LE(fastest, 1e-6);
  EXPECT_LE(worst, 1e-3);
}

}  // namespace
}  // namespace ice
