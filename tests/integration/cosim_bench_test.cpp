// `cosim bench` end to end on a small suite of shallow-water runs: a
// refinement study (two grids of Stoker's dam break) and a scenario whose
// case is broken. The broken run is a row that says it failed and why, the
// others are measured, the bench exits 3 (a run failed), and a second
// `cosim bench --resume` on the same directory keeps the finished runs and
// runs the rest again. Bad arguments exit 2 before anything runs.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

std::string suite_text(const fs::path& configs) {
  return fmt::format(R"(kind: bench_suite
name: small
scenarios:
  - name: stoker
    backends:
      swe:
        case: {0}/swe/stoker_dam_break.yaml
        levels:
          - {{label: 50 cells, cells: 50, set: {{case: {{mesh: {{from: 0.0, to: 1.0, cells: 50}}}}}}}}
          - {{label: 100 cells, cells: 100, set: {{case: {{mesh: {{from: 0.0, to: 1.0, cells: 100}}}}}}}}
    metrics:
      - name: depth_l1
        unit: m
        quantity: {{profile: {{field: depth, from: [0.0], to: [1.0], points: 201, time: 0.1}}}}
        reference: {{analytic: dam_break_depth,
                    parameters: {{left_depth: 1.0, right_depth: 0.5, dam_position: 0.5}}}}
        error: mean_abs
        tolerance: 0.01
  - name: broken
    backends:
      swe: {{case: {0}/swe/lake_at_rest_1d.yaml, set: {{case: {{scheme.flux: roee}}}}}}
    metrics:
      - name: fastest_water
        unit: m/s
        quantity: {{time_series: {{file: water.csv, column: "speed_max [m/s]", at: max}}}}
)",
                     configs.string());
}

TEST(CosimBench, AFailedRunIsARowThatSaysWhyAndTheRestAreMeasured) {
  const fs::path dir = fresh_directory("cosim_bench_small");
  write_text(dir / "suite.yaml", suite_text(fs::path(COSIM_SOURCE_DIR) / "configs"));
  const auto bench = [&](std::vector<std::string> flags) {
    std::vector<std::string> args{binary("cosim").string(), "bench", (dir / "suite.yaml").string(),
                                  "--output", (dir / "report").string()};
    args.insert(args.end(), flags.begin(), flags.end());
    return run(args, std::chrono::seconds(300));
  };
  ProcessResult r = bench({});
  EXPECT_EQ(r.exit_code, 3) << r.output;
  const std::string csv = read_text(dir / "report" / "results.csv");
  fmt::print("{}", csv);
  EXPECT_NE(csv.find("stoker,swe,50 cells,50,depth_l1,m,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("stoker,swe,100 cells,100,depth_l1,m,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("broken,swe,,,fastest_water,m/s,,,,,,unavailable,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",failed,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("swe_fluid exited with status 2: "), std::string::npos) << csv;
  EXPECT_NE(csv.find("scheme.flux"), std::string::npos) << csv;  // the console's last words
  EXPECT_NE(csv.find(",pass,"), std::string::npos) << csv;
  const std::string report = read_text(dir / "report" / "report.md");
  EXPECT_NE(report.find("**swe** did not finish (failed)"), std::string::npos) << report;
  // The failing run's own console names the key.
  EXPECT_NE(
      read_text(dir / "report" / "runs" / "broken" / "swe" / "console.log").find("scheme.flux"),
      std::string::npos);
  const auto summary = nlohmann::json::parse(read_text(dir / "report" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 3);
  EXPECT_EQ(summary["metrics"]["runs_not_finished"]["value"], 1);
  EXPECT_TRUE(fs::exists(dir / "report" / "plots" / "stoker__depth_l1_convergence.png"));

  // A dry run says which runs would be kept.
  const ProcessResult dry = bench({"--resume", "--dry-run"});
  EXPECT_EQ(dry.exit_code, 0) << dry.output;
  EXPECT_NE(dry.output.find("stoker/swe@50 cells"), std::string::npos) << dry.output;
  EXPECT_NE(dry.output.find("(kept)"), std::string::npos) << dry.output;
  EXPECT_NE(dry.output.find("broken/swe"), std::string::npos);

  // Resumed: the two finished runs are kept, the broken one is tried again.
  r = bench({"--resume"});
  EXPECT_EQ(r.exit_code, 3);
  const std::string log = read_text(dir / "report" / "log.txt");
  EXPECT_NE(log.find("stoker/swe@50 cells: finished by an earlier run"), std::string::npos) << log;
  EXPECT_NE(log.find("stoker/swe@100 cells: finished by an earlier run"), std::string::npos);
  EXPECT_NE(log.find("broken/swe: started"), std::string::npos);
}

TEST(CosimBench, BadArgumentsExitTwoBeforeAnythingRuns) {
  const fs::path dir = fresh_directory("cosim_bench_bad");
  write_text(dir / "suite.yaml", suite_text(fs::path(COSIM_SOURCE_DIR) / "configs"));
  ProcessResult r = run({binary("cosim").string(), "bench", (dir / "suite.yaml").string(),
                         "--output", (dir / "out").string(), "--only", "stokerr"},
                        std::chrono::seconds(60));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("no such scenario; it has: stoker, broken"), std::string::npos)
      << r.output;
  r = run({binary("cosim").string(), "bench", (dir / "suite.yaml").string(), "--output",
           (dir / "out").string(), "--resolution", "fine"},
          std::chrono::seconds(60));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  write_text(dir / "typo.yaml",
             replaced(suite_text(fs::path(COSIM_SOURCE_DIR) / "configs"),
                      "    backends:\n      swe:\n", "    backend:\n      swe:\n"));
  r = run({binary("cosim").string(), "bench", (dir / "typo.yaml").string(), "--output",
           (dir / "out").string()},
          std::chrono::seconds(60));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("typo.yaml:5:"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "runs"));
}

}  // namespace
}  // namespace cosim::testing
