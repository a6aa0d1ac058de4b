// `cosim run` with the coupler's implicit momentum exchange between a "fluid"
// and a "solid" test participant on different grids: the momentum each side
// receives over a window is the closed-form two-phase impulse (Tran et al.,
// MPMICE, eq. 131) and the two add up to zero.

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
constexpr double drag = 1.0e5;          // K [kg m^-3 s^-1]
constexpr double rho_f = 600.0;         // fluid bulk density [kg m^-3]
constexpr double rho_s = 1590.0;        // solid bulk density
constexpr double u_f = 0.1, u_s = 0.0;  // each velocity component [m/s]

void write_case(const fs::path& dir) {
  write_text(dir / "job.yaml", R"(kind: job
name: momentum
end_time: 0.025
window: 2.5e-3
participants:
  water:
    executable: cosim_test_participant
    config: water.yaml
    meshes: {grid: {kind: uniform_grid, dim: 2}}
    writes: {fluid_velocity: grid, fluid_bulk_density: grid}
    reads: {momentum_exchange_impulse: grid}
  soil:
    executable: cosim_test_participant
    config: soil.yaml
    meshes: {grid: {kind: uniform_grid, dim: 2}}
    writes: {solid_fraction: grid, solid_velocity: grid, solid_bulk_density: grid}
    reads: {momentum_exchange_impulse: grid}
momentum_exchange:
  fluid: water
  solid: soil
  mesh: water.grid
  drag: {law: constant, coefficient: 1.0e5}
)");
  write_text(dir / "water.yaml", R"(kind: test_participant
dt: 1.0e-3
mesh: {dim: 2, origin: [0.0, 0.0], spacing: [0.1, 0.1], cells: [10, 10]}
writes:
  - {name: fluid_velocity, unit: m/s, components: 2, function: [0.1, 0, 0, 0, 0]}
  - {name: fluid_bulk_density, unit: kg/m^3, function: [600.0, 0, 0, 0, 0]}
reads:
  - {name: momentum_exchange_impulse, unit: kg m/s, components: 2, quantity: extensive, time: integral}
)");
  write_text(dir / "soil.yaml", R"(kind: test_participant
dt: 7.0e-4
mesh: {dim: 2, origin: [0.0, 0.0], spacing: [0.125, 0.125], cells: [8, 8], location: node}
writes:
  - {name: solid_fraction, function: [0.4, 0, 0, 0, 0]}
  - {name: solid_velocity, unit: m/s, components: 2, function: [0.0, 0, 0, 0, 0]}
  - {name: solid_bulk_density, unit: kg/m^3, function: [1590.0, 0, 0, 0, 0]}
reads:
  - {name: momentum_exchange_impulse, unit: kg m/s, components: 2, quantity: extensive, time: integral}
)");
}

TEST(MomentumExchange, ImpulsesMatchTheClosedFormAndCancel) {
  const fs::path dir = fresh_directory("e2e_momentum");
  write_case(dir);
  const auto r = run({binary("cosim").string(), "run", (dir / "job.yaml").string(), "--output",
                      (dir / "run").string()},
                     std::chrono::seconds(120));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto fluid = read_csv(dir / "run" / "water" / "momentum_exchange_impulse_applied.csv");
  const auto solid = read_csv(dir / "run" / "soil" / "momentum_exchange_impulse_applied.csv");
  ASSERT_EQ(fluid.size(), 10u);
  ASSERT_EQ(solid.size(), 10u);
  // Per unit volume and component: J_f = (u_s - u_f) / (1/(dt K) + 1/rho_f + 1/rho_s);
  // the domain is 1 m^2 and there are two components.
  const double expected = 2.0 * (u_s - u_f) / (1.0 / (window * drag) + 1.0 / rho_f + 1.0 / rho_s);
  EXPECT_EQ(fluid[0][2], 0.0);  // window 1 applies the exchange of the initial state (dt = 0)
  double worst_balance = 0.0, worst_value = 0.0;
  for (std::size_t k = 1; k < fluid.size(); ++k) {
    worst_balance =
        std::max(worst_balance, std::abs(fluid[k][2] + solid[k][2]) / std::abs(fluid[k][2]));
    worst_value = std::max(worst_value, std::abs(fluid[k][2] - expected) / std::abs(expected));
  }
  std::printf(
      "momentum exchange: impulse %.12g kg m/s per window (closed form %.12g); "
      "relative error %.3e, fluid + solid balance %.3e\n",
      fluid[1][2], expected, worst_value, worst_balance);
  EXPECT_LE(worst_value, 1e-12);
  EXPECT_LE(worst_balance, 1e-12);
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_LE(summary["metrics"]["max_momentum_exchange_balance_error"]["value"].get<double>(),
            1e-12);
  EXPECT_GT(summary["wall_time_s"]["phases"]["exchange"].get<double>(), 0.0);
}

TEST(MomentumExchange, JobMissingAPhaseFieldIsRefusedBeforeStarting) {
  const fs::path dir = fresh_directory("e2e_momentum_bad");
  write_case(dir);
  std::string job = read_text(dir / "job.yaml");
  job.replace(job.find(", solid_bulk_density: grid"),
              std::string(", solid_bulk_density: grid").size(), "");
  write_text(dir / "job.yaml", job);
  const auto r = run({binary("cosim").string(), "validate", (dir / "job.yaml").string()},
                     std::chrono::seconds(30));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, ::testing::HasSubstr("job.yaml:19:3"));
  EXPECT_THAT(r.output,
              ::testing::HasSubstr("needs participant 'soil' to write 'solid_bulk_density'"));
}

// solved_by: fluid. The "fluid" writes, as the rate of the window integral,
// the momentum its own steps gave the solid (1.2 kg m/s per m^3 and second in
// x); the coupler sends it K from the law (checked by the fluid at every
// window) and hands the solid that momentum through a conservative map onto
// the solid's other grid.
void write_fluid_solved_case(const fs::path& dir) {
  write_case(dir);
  std::string job = read_text(dir / "job.yaml");
  job.replace(job.find("    writes: {fluid_velocity: grid, fluid_bulk_density: grid}\n    reads: "
                       "{momentum_exchange_impulse: grid}"),
              std::string("    writes: {fluid_velocity: grid, fluid_bulk_density: grid}\n    "
                          "reads: {momentum_exchange_impulse: grid}")
                  .size(),
              "    writes: {fluid_velocity: grid, fluid_bulk_density: grid, "
              "momentum_exchange_impulse: grid}\n    reads: {drag_coefficient: grid}");
  job += "  solved_by: fluid\n";
  write_text(dir / "job.yaml", job);
  write_text(dir / "water.yaml", R"(kind: test_participant
dt: 1.0e-3
mesh: {dim: 2, origin: [0.0, 0.0], spacing: [0.1, 0.1], cells: [10, 10]}
writes:
  - {name: fluid_velocity, unit: m/s, components: 2, function: [0.1, 0, 0, 0, 0]}
  - {name: fluid_bulk_density, unit: kg/m^3, function: [600.0, 0, 0, 0, 0]}
  - {name: momentum_exchange_impulse, unit: kg m/s, components: 2, quantity: extensive, time: integral, function: [1.2, 0, 0, 0, 0]}
reads:
  - {name: drag_coefficient, unit: kg/(m^3 s), function: [1.0e5, 0, 0, 0, 0], tolerance: 1.0e-6}
)");
}

TEST(MomentumExchange, SolvedByTheFluidSendsKAndHandsTheSolidWhatTheFluidGave) {
  const fs::path dir = fresh_directory("e2e_momentum_fluid");
  write_fluid_solved_case(dir);
  const auto r = run({binary("cosim").string(), "run", (dir / "job.yaml").string(), "--output",
                      (dir / "run").string()},
                     std::chrono::seconds(120));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto solid = read_csv(dir / "run" / "soil" / "momentum_exchange_impulse_applied.csv");
  ASSERT_EQ(solid.size(), 10u);
  // 1.2 per m^3 and second over the 1 m^2 domain, 2 components, one window.
  const double expected = 2.0 * 1.2 * window;
  double worst = 0.0;
  for (std::size_t k = 1; k < solid.size(); ++k)
    worst = std::max(worst, std::abs(solid[k][2] - expected) / expected);
  std::printf(
      "solved_by fluid: the solid receives %.12g kg m/s per window (fluid gave %.12g); "
      "relative error %.3e\n",
      solid[1][2], expected, worst);
  EXPECT_LE(worst, 1e-12);
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_LE(summary["metrics"]["max_momentum_exchange_balance_error"]["value"].get<double>(),
            1e-12);
}

TEST(MomentumExchange, SolvedByTheFluidNeedsItsFieldsTheOtherWayRound) {
  const fs::path dir = fresh_directory("e2e_momentum_fluid_bad");
  write_fluid_solved_case(dir);
  const std::string good = read_text(dir / "job.yaml");
  const auto refused = [&](const std::string& from, const std::string& to, const char* message) {
    std::string job = good;
    job.replace(job.find(from), from.size(), to);
    write_text(dir / "job.yaml", job);
    const auto r = run({binary("cosim").string(), "validate", (dir / "job.yaml").string()},
                       std::chrono::seconds(30));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_THAT(r.output, ::testing::HasSubstr(message)) << r.output;
  };
  refused("reads: {drag_coefficient: grid}", "reads: {}",
          "needs participant 'water' to read 'drag_coefficient'");
  refused(", momentum_exchange_impulse: grid}\n    reads: {drag_coefficient: grid}",
          "}\n    reads: {drag_coefficient: grid}",
          "needs participant 'water' to write 'momentum_exchange_impulse'");
  refused("reads: {drag_coefficient: grid}",
          "reads: {drag_coefficient: grid, momentum_exchange_impulse: grid}",
          "both writes and reads 'momentum_exchange_impulse'");
  refused("  solved_by: fluid\n", "  solved_by: fluids\n", "solved_by");
}

}  // namespace
}  // namespace cosim::testing
