// `cosim run` with the coupler's implicit energy exchange (Tran et al.,
// MPMICE, eq. 23) between a "fluid" and a "solid" test participant on
// different grids: the heat each receives over a window is the closed form
//   q V,  q = (T_s - T_f) / (1 / (dt H) + 1 / C_f + 1 / C_s),
// the two add up to zero, and a job missing a field is refused at its key.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

constexpr double window = 2.5e-3;
constexpr double coefficient = 4.0e6;  // H [W m^-3 K^-1]
constexpr double c_f = 1.67e6;         // rhobar_f c_f [J m^-3 K^-1]
constexpr double c_s = 1.25e6;
constexpr double t_f = 293.0, t_s = 303.0;

void write_case(const fs::path& dir) {
  write_text(dir / "job.yaml", R"(kind: job
name: energy
end_time: 0.025
window: 2.5e-3
participants:
  water:
    executable: cosim_test_participant
    config: water.yaml
    meshes: {grid: {kind: uniform_grid, dim: 2}}
    writes: {fluid_temperature: grid, fluid_heat_capacity: grid}
    reads: {heat_exchange_energy: grid}
  rock:
    executable: cosim_test_participant
    config: rock.yaml
    meshes: {grid: {kind: uniform_grid, dim: 2}}
    writes: {solid_temperature: grid, solid_heat_capacity: grid}
    reads: {heat_exchange_energy: grid}
energy_exchange:
  fluid: water
  solid: rock
  mesh: water.grid
  coefficient: 4.0e6
)");
  write_text(dir / "water.yaml", R"(kind: test_participant
dt: 1.0e-3
mesh: {dim: 2, origin: [0.0, 0.0], spacing: [0.1, 0.1], cells: [10, 10]}
writes:
  - {name: fluid_temperature, unit: K, function: [293.0, 0, 0, 0, 0]}
  - {name: fluid_heat_capacity, unit: J/(m^3 K), function: [1.67e6, 0, 0, 0, 0]}
reads:
  - {name: heat_exchange_energy, unit: J, quantity: extensive, time: integral}
)");
  write_text(dir / "rock.yaml", R"(kind: test_participant
dt: 7.0e-4
mesh: {dim: 2, origin: [0.0, 0.0], spacing: [0.125, 0.125], cells: [8, 8]}
writes:
  - {name: solid_temperature, unit: K, function: [303.0, 0, 0, 0, 0]}
  - {name: solid_heat_capacity, unit: J/(m^3 K), function: [1.25e6, 0, 0, 0, 0]}
reads:
  - {name: heat_exchange_energy, unit: J, quantity: extensive, time: integral}
)");
}

TEST(EnergyExchange, HeatMatchesTheClosedFormAndCancels) {
  const fs::path dir = fresh_directory("e2e_energy");
  write_case(dir);
  const auto r = run({binary("cosim").string(), "run", (dir / "job.yaml").string(), "--output",
                      (dir / "run").string()},
                     std::chrono::seconds(120));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto fluid = read_csv(dir / "run" / "water" / "heat_exchange_energy_applied.csv");
  const auto solid = read_csv(dir / "run" / "rock" / "heat_exchange_energy_applied.csv");
  ASSERT_EQ(fluid.size(), 10u);
  ASSERT_EQ(solid.size(), 10u);
  // The domain is 1 m^2.
  const double expected = (t_s - t_f) / (1.0 / (window * coefficient) + 1.0 / c_f + 1.0 / c_s);
  EXPECT_EQ(fluid[0][2], 0.0);  // window 1 applies the exchange of the initial state (dt = 0)
  double worst_balance = 0.0, worst_value = 0.0;
  for (std::size_t k = 1; k < fluid.size(); ++k) {
    worst_balance =
        std::max(worst_balance, std::abs(fluid[k][2] + solid[k][2]) / std::abs(fluid[k][2]));
    worst_value = std::max(worst_value, std::abs(fluid[k][2] - expected) / std::abs(expected));
  }
  std::printf(
      "energy exchange: %.12g J per window to the fluid (closed form %.12g); relative error "
      "%.3e, fluid + solid balance %.3e\n",
      fluid[1][2], expected, worst_value, worst_balance);
  EXPECT_LE(worst_value, 1e-12);
  EXPECT_LE(worst_balance, 1e-12);
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_LE(summary["metrics"]["max_energy_exchange_balance_error"]["value"].get<double>(), 1e-12);
}

TEST(EnergyExchange, JobMissingAFieldIsRefusedBeforeStarting) {
  const fs::path dir = fresh_directory("e2e_energy_bad");
  write_case(dir);
  std::string job = read_text(dir / "job.yaml");
  job.replace(job.find(", solid_heat_capacity: grid"),
              std::string(", solid_heat_capacity: grid").size(), "");
  write_text(dir / "job.yaml", job);
  const auto r = run({binary("cosim").string(), "validate", (dir / "job.yaml").string()},
                     std::chrono::seconds(30));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, ::testing::HasSubstr("job.yaml:19:3"));
  EXPECT_THAT(r.output,
              ::testing::HasSubstr("needs participant 'rock' to write 'solid_heat_capacity'"));
}

}  // namespace
}  // namespace cosim::testing
