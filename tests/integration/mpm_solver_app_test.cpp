// End to end: the `mpm_solver` executable on small cases: what a good run
// leaves behind, exit 2 with a located message for bad input, exit 4 for a
// numerical failure that keeps the snapshots written before it.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// An elastic block above a rigid floor on a 1 m x 1 m grid (h = 0.05 m).
// Line numbers matter: tests expect errors at them.
const char* const drop_case = R"(kind: mpm_case
name: drop
dimension: 2
grid: {origin: [0, 0], upper: [1, 1], cells: [20, 20]}
time: {end_time: 0.05, safety_factor: 0.4}
gravity: [0, -9.81]
materials:
  rubber: {type: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
bodies:
  - name: block
    material: rubber
    geometry: {box: {min: [0.4, 0.3], max: [0.6, 0.5]}}
    initial_velocity: [0, -1]
  - name: floor
    rigid: {motion: fixed}
    density: 2000
    geometry: {box: {min: [0, 0], max: [1, 0.1]}}
contact: {enabled: true, friction: 0.3}
boundaries: {x_min: slip, x_max: slip, y_min: fixed, y_max: slip}
probes:
  - {name: centre, body: block, position: [0.5, 0.4]}
output: {every: 0.01, probe_every: 0.005}
)";

struct SolverRun {
  ProcessResult result;
  fs::path output;
  nlohmann::json summary;
};

// Writes `text` as <dir>/case.yaml (plus extra files) and runs the solver on it.
SolverRun run_case(const std::string& name, const std::string& text,
                   const std::vector<std::pair<std::string, std::string>>& files = {}) {
  const fs::path dir = fresh_directory("mpm_solver_app/" + name);
  write_text(dir / "case.yaml", text);
  for (const auto& [file, contents] : files) write_text(dir / file, contents);
  SolverRun run;
  run.output = dir / "out";
  run.result =
      cosim::testing::run({binary("mpm_solver").string(), "--config", (dir / "case.yaml").string(),
                           "--output", run.output.string(), "--threads", "1"},
                          std::chrono::seconds(120));
  if (fs::exists(run.output / "summary.json"))
    run.summary = nlohmann::json::parse(read_text(run.output / "summary.json"));
  return run;
}

void expect_bad_input(const SolverRun& run, const std::string& located, const std::string& what) {
  EXPECT_EQ(run.result.exit_code, 2) << run.result.output;
  EXPECT_THAT(run.result.output, HasSubstr(located));
  EXPECT_THAT(run.result.output, HasSubstr(what));
  ASSERT_TRUE(run.summary.is_object()) << "summary.json missing";
  EXPECT_EQ(run.summary["status"]["exit_code"], 2);
  EXPECT_THAT(run.summary["status"]["message"].get<std::string>(), HasSubstr(located));
}

TEST(MpmSolverApp, GoodRunWritesSummarySnapshotsAndProbes) {
  const SolverRun run = run_case("good", drop_case);
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  EXPECT_TRUE(fs::exists(run.output / "log.txt"));
  EXPECT_EQ(run.summary["status"]["exit_code"], 0);
  EXPECT_EQ(run.summary["program"], "mpm_solver");
  EXPECT_EQ(run.summary["config"]["hash"].get<std::string>().size(), 16u);
  EXPECT_GT(run.summary["steps"].get<int>(), 10);
  EXPECT_GT(run.summary["metrics"]["particle_updates_per_second"]["value"].get<double>(), 0.0);
  const double mass_change = run.summary["conserved"]["mass"]["relative_change"].get<double>();
  EXPECT_LE(std::abs(mass_change), 1e-12) << "relative mass change " << mass_change;

  // Snapshots at t = 0, 0.01, ..., 0.05.
  const std::string xdmf = read_text(run.output / "particles.xdmf");
  for (int k = 0; k <= 5; ++k) {
    EXPECT_TRUE(fs::exists(run.output / fmt::format("particles_{:06d}.h5", k))) << k;
  }
  EXPECT_FALSE(fs::exists(run.output / "particles_000006.h5"));
  for (const char* field : {"velocity", "displacement", "stress", "effective_stress", "strain",
                            "plastic_strain", "porosity", "pore_pressure", "damage", "body"})
    EXPECT_THAT(xdmf, HasSubstr(fmt::format("Name=\"{}\"", field)));
  EXPECT_THAT(xdmf, HasSubstr("Tensor6"));

  // probes.csv: t = 0, 0.005, ..., 0.05; the block falls (gravity and
  // initial velocity) until it meets the floor at 0.1 m - not within 0.05 s.
  const std::string header = read_text(run.output / "probes.csv").substr(0, 200);
  EXPECT_THAT(header, HasSubstr("time [s],centre_displacement_x [m],centre_displacement_y [m],"
                                "centre_velocity_x [m/s]"));
  const auto rows = read_csv(run.output / "probes.csv");
  ASSERT_EQ(rows.size(), 11u);
  ASSERT_EQ(rows[10].size(), 11u);  // time + (2 + 2 + 4 + 2) per probe
  EXPECT_NEAR(rows[10][0], 0.05, 1e-12);
  const double t = rows[10][0];
  const double expected = -1.0 * t - 0.5 * 9.81 * t * t;
  const double error = std::abs(rows[10][2] - expected);
  EXPECT_LE(error, 0.01 * std::abs(expected))
      << "free fall displacement " << rows[10][2] << " m vs " << expected << " m, error " << error
      << " m (tolerance 1%)";
}

TEST(MpmSolverApp, IncompressibleMaterialIsBadInput) {
  expect_bad_input(run_case("nu", replaced(drop_case, "poisson_ratio: 0.3", "poisson_ratio: 0.5")),
                   "case.yaml:8:", "key 'materials.rubber.poisson_ratio'");
}

TEST(MpmSolverApp, NonPositiveModulusIsBadInput) {
  expect_bad_input(
      run_case("E", replaced(drop_case, "youngs_modulus: 1.0e6", "youngs_modulus: -1")),
      "case.yaml:8:", "key 'materials.rubber.youngs_modulus'");
}

TEST(MpmSolverApp, NonPositiveDensityIsBadInput) {
  expect_bad_input(run_case("density", replaced(drop_case, "density: 1000", "density: 0")),
                   "case.yaml:8:", "key 'materials.rubber.density'");
}

TEST(MpmSolverApp, ParticlesOutsideTheGridAreBadInput) {
  expect_bad_input(run_case("outside", replaced(drop_case, "max: [0.6, 0.5]", "max: [0.6, 1.1]")),
                   "case.yaml:12:15: key 'bodies[0].geometry'",
                   "body 'block' has particles outside the grid, the first at (0.4125, 1.0125)");
}

TEST(MpmSolverApp, UnknownKeyIsBadInputWithASuggestion) {
  expect_bad_input(run_case("unknown_key", replaced(drop_case, "safety_factor:", "safety_facter:")),
                   "case.yaml:5:", "unknown key 'safety_facter'; did you mean 'safety_factor'?");
}

TEST(MpmSolverApp, BadVelocityHistoryLineIsBadInput) {
  const std::string text = replaced(drop_case, "rigid: {motion: fixed}",
                                    "rigid: {motion: prescribed, velocity_history: shake.csv}");
  expect_bad_input(
      run_case("history", text,
               {{"shake.csv", "time [s],vx [m/s],vy [m/s]\n0,0,0\n0.1,0.1,0\n0.2,0.1\n"}}),
      "shake.csv:4:1: key 'bodies[1].rigid.velocity_history'", "expected 3 values");
}

TEST(MpmSolverApp, ParticlesLeavingTheGridAreANumericalFailureThatKeepsSnapshots) {
  // No floor and a free bottom face: the block falls out of the grid at
  // about t = 0.13 s, after the snapshots at 0, 0.02, ..., 0.12 s.
  std::string text = replaced(drop_case, "end_time: 0.05", "end_time: 1.0");
  text = replaced(text, "y_min: fixed", "y_min: free");
  text = replaced(text, "every: 0.01", "every: 0.02");
  text = replaced(text, "min: [0, 0], max: [1, 0.1]", "min: [0.9, 0.9], max: [1, 1]");
  const SolverRun run = run_case("leaves_grid", text);
  EXPECT_EQ(run.result.exit_code, 4) << run.result.output;
  EXPECT_THAT(run.result.output, HasSubstr("left the grid"));
  EXPECT_EQ(run.summary["status"]["exit_code"], 4);
  EXPECT_THAT(run.summary["status"]["message"].get<std::string>(), HasSubstr("left the grid"));
  const std::string xdmf = read_text(run.output / "particles.xdmf");
  for (int k = 0; k <= 5; ++k) {
    EXPECT_TRUE(fs::exists(run.output / fmt::format("particles_{:06d}.h5", k))) << k;
    EXPECT_THAT(xdmf, HasSubstr(fmt::format("particles_{:06d}.h5", k)));
  }
}

TEST(MpmSolverApp, TimeStepBelowTheMinimumIsANumericalFailure) {
  const SolverRun run =
      run_case("min_time_step",
               replaced(drop_case, "safety_factor: 0.4", "safety_factor: 0.4, min_time_step: 1.0"));
  EXPECT_EQ(run.result.exit_code, 4) << run.result.output;
  EXPECT_THAT(run.result.output, HasSubstr("fell below time.min_time_step = 1 s at t = 0 s"));
  EXPECT_EQ(run.summary["status"]["exit_code"], 4);
  EXPECT_TRUE(fs::exists(run.output / "particles_000000.h5"));
}

TEST(MpmSolverApp, HelpConfigListsCaseAndMaterialKeys) {
  const auto result = cosim::testing::run({binary("mpm_solver").string(), "--help-config"},
                                          std::chrono::seconds(30));
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_THAT(result.output, HasSubstr("bodies[].geometry.box.min"));
  EXPECT_THAT(result.output, HasSubstr("materials.<name> with type: mohr_coulomb"));
}

TEST(MpmSolverApp, MissingArgumentsAreBadInput) {
  const auto result = cosim::testing::run({binary("mpm_solver").string(), "--output", "x"},
                                          std::chrono::seconds(30));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.output, HasSubstr("--config"));
}

TEST(MpmSolverApp, ExampleCasesRun) {
  for (const char* example : {"elastic_block_drop", "sand_column_collapse"}) {
    const fs::path output = fresh_directory(std::string("mpm_solver_app/example_") + example);
    const auto result = cosim::testing::run(
        {binary("mpm_solver").string(), "--config",
         (fs::path(COSIM_SOURCE_DIR) / "configs" / "mpm" / (std::string(example) + ".yaml"))
             .string(),
         "--output", output.string()},
        std::chrono::seconds(300));
    EXPECT_EQ(result.exit_code, 0) << example << "\n" << result.output;
    EXPECT_TRUE(fs::exists(output / "particles.xdmf")) << example;
  }
}

}  // namespace
}  // namespace cosim::testing
