// Validation of the coupler's implicit momentum exchange against Darcy's law
// (Tran et al., MPMICE, eq. 98): water driven by the pressure gradient
// through a held porous column of solid fraction phi_s and grain size d
// reaches U_f = (1/n) d^2 (1 - phi_s)^3 / (180 phi_s^2 mu) dp/L, n = 1 - phi_s.
//
// The fluid participant integrates the driving force n dp/L per unit volume
// over its own sub-steps (1e-3 s in a 2.5e-3 s window); the coupler exchanges
// momentum with the Kozeny-Carman coefficient (eq. 29); the solid is held
// (bulk density 1e20 kg/m^3, as the fixed column). At steady state the
// velocity after the exchange equals Darcy's exactly, whatever the window.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "bench/darcy_column.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using bench::DarcyColumn;

namespace fs = std::filesystem;

constexpr double grain_size = 1.0e-3;  // d [m]
constexpr double viscosity = 1.0e-3;   // mu [Pa s]
constexpr double water_density = 1000.0;
constexpr double atmosphere = 101325.0;
constexpr double length = 1.0;  // L [m]

double run_case(const fs::path& dir, double phi_s, double dp) {
  const double n = 1.0 - phi_s;
  write_text(dir / "job.yaml", fmt::format(R"(kind: job
name: darcy
end_time: 0.25
window: 2.5e-3
participants:
  water:
    executable: cosim_test_participant
    config: water.yaml
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{fluid_velocity: grid, fluid_bulk_density: grid}}
    reads: {{momentum_exchange_impulse: grid}}
  column:
    executable: cosim_test_participant
    config: column.yaml
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{solid_fraction: grid, solid_velocity: grid, solid_bulk_density: grid}}
    reads: {{momentum_exchange_impulse: grid}}
momentum_exchange:
  fluid: water
  solid: column
  mesh: water.grid
  drag: {{law: kozeny_carman, grain_size: {}, fluid_viscosity: {}}}
)",
                                           grain_size, viscosity));
  write_text(dir / "water.yaml",
             fmt::format(R"(kind: test_participant
dt: 1.0e-3
mesh: {{dim: 1, origin: [0.0], spacing: [0.05], cells: [20]}}
writes:
  - {{name: fluid_velocity, unit: m/s, function: [0, 0, 0, 0, 0]}}
  - {{name: fluid_bulk_density, unit: kg/m^3, function: [{}, 0, 0, 0, 0]}}
reads:
  - {{name: momentum_exchange_impulse, unit: kg m/s, quantity: extensive, time: integral}}
dynamics: {{velocity: fluid_velocity, impulse: momentum_exchange_impulse, bulk_density: {}, body_force: [{}]}}
)",
                         water_density * n, water_density * n, n * dp / length));
  write_text(dir / "column.yaml", fmt::format(R"(kind: test_participant
dt: 7.0e-4
mesh: {{dim: 1, origin: [0.0], spacing: [0.1], cells: [10], location: node}}
writes:
  - {{name: solid_fraction, function: [{}, 0, 0, 0, 0]}}
  - {{name: solid_velocity, unit: m/s, function: [0, 0, 0, 0, 0]}}
  - {{name: solid_bulk_density, unit: kg/m^3, function: [1.0e20, 0, 0, 0, 0]}}
reads:
  - {{name: momentum_exchange_impulse, unit: kg m/s, quantity: extensive, time: integral}}
)",
                                              phi_s));
  const auto r = run({binary("cosim").string(), "run", (dir / "job.yaml").string(), "--output",
                      (dir / "run").string()},
                     std::chrono::seconds(120));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const auto rows = read_csv(dir / "run" / "water" / "fluid_velocity_after_exchange.csv");
  return rows.empty() ? 0.0 : rows.back()[2];
}

TEST(DarcyValidation, SteadyVelocityMatchesEquation98ForAllFifteenCases) {
  constexpr double tolerance = 1e-10;
  double worst = 0.0;
  std::printf("%8s %8s %16s %16s %10s\n", "phi_s", "dp[atm]", "U_f [m/s]", "Darcy [m/s]",
              "rel.error");
  for (double phi_s : {0.6, 0.62, 0.66, 0.68, 0.7}) {
    for (double dp_atm : {0.25, 0.5, 1.0}) {
      const fs::path dir = fresh_directory(fmt::format("darcy_{}_{}", phi_s, dp_atm));
      const double dp = dp_atm * atmosphere;
      const double u = run_case(dir, phi_s, dp);
      const double expected = DarcyColumn{grain_size, viscosity, length}.pore_velocity(phi_s, dp);
      const double error = std::abs(u - expected) / expected;
      worst = std::max(worst, error);
      std::printf("%8.2f %8.2f %16.10g %16.10g %10.2e\n", phi_s, dp_atm, u, expected, error);
      EXPECT_LE(error, tolerance) << "phi_s = " << phi_s << ", dp = " << dp_atm << " atm";
    }
  }
  std::printf("Darcy validation: max relative error %.3e (tolerance %.0e)\n", worst, tolerance);
}

}  // namespace
}  // namespace cosim::testing
