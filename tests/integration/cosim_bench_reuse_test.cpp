// `cosim bench` never mixes two calls in one report directory: a non-empty
// --output is refused untouched; --resume keeps the finished runs whose
// inputs did not change and re-runs the others each in a cleared run
// directory; --overwrite clears the report and starts afresh (and refuses
// to clear the suite file it was given).
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

// Two short runs of a lake at rest: levels a and b.
std::string suite_text(int cells_of_b) {
  return fmt::format(R"(kind: bench_suite
name: lakes
scenarios:
  - name: lake
    backends:
      swe:
        case: {0}/configs/swe/lake_at_rest_1d.yaml
        levels:
          - {{label: a, cells: 20, set: {{case: {{mesh.cells: 20, time.end_time: 0.1, output.every: 0.05}}}}}}
          - {{label: b, cells: {1}, set: {{case: {{mesh.cells: {1}, time.end_time: 0.1, output.every: 0.05}}}}}}
    metrics:
      - name: fastest_water
        unit: m/s
        quantity: {{time_series: {{file: water.csv, column: "speed_max [m/s]", at: max}}}}
)",
                     COSIM_SOURCE_DIR, cells_of_b);
}

TEST(CosimBenchReuse, ANonEmptyReportIsRefusedResumedOrOverwritten) {
  const fs::path dir = fresh_directory("cosim_bench_reuse");
  const fs::path report = dir / "report";
  const auto bench = [&](int cells_of_b, std::vector<std::string> flags) {
    write_text(dir / "suite.yaml", suite_text(cells_of_b));
    std::vector<std::string> args{binary("cosim").string(), "bench", (dir / "suite.yaml").string(),
                                  "--output", report.string()};
    args.insert(args.end(), flags.begin(), flags.end());
    return run(args, std::chrono::seconds(300));
  };
  ProcessResult r = bench(40, {});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path run_b = report / "runs" / "lake" / "swe--b" / "out";
  write_text(report / "notes.txt", "an earlier call's");
  write_text(run_b / "swe_000099.h5", "stale");

  // Before: the second call went on in the first one's directory.
  const std::string log = read_text(report / "log.txt");
  r = bench(40, {});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("is not empty"));
  EXPECT_THAT(r.output, HasSubstr("--resume"));
  EXPECT_EQ(read_text(report / "log.txt"), log);
  EXPECT_TRUE(fs::exists(run_b / "swe_000099.h5"));

  // Resumed with level b changed: a kept, b run again from a cleared directory.
  r = bench(41, {"--resume"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::string now = read_text(report / "log.txt");
  EXPECT_THAT(now, HasSubstr("lake/swe@a: finished by an earlier run"));
  EXPECT_THAT(now, HasSubstr("lake/swe@b: started"));
  EXPECT_FALSE(fs::exists(run_b / "swe_000099.h5"));
  EXPECT_TRUE(fs::exists(run_b / "swe_000001.h5"));
  EXPECT_TRUE(fs::exists(report / "notes.txt"));

  // Overwritten: everything afresh.
  r = bench(41, {"--overwrite"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  now = read_text(report / "log.txt");
  EXPECT_THAT(now, Not(HasSubstr("finished by an earlier run")));
  EXPECT_THAT(now, HasSubstr("lake/swe@a: started"));
  EXPECT_FALSE(fs::exists(report / "notes.txt"));

  // The suite inside the report directory is not cleared with it.
  write_text(report / "suite.yaml", suite_text(41));
  r = run({binary("cosim").string(), "bench", (report / "suite.yaml").string(), "--output",
           report.string(), "--overwrite"},
          std::chrono::seconds(60));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("which holds the suite file"));
  EXPECT_TRUE(fs::exists(report / "suite.yaml"));
}

}  // namespace
}  // namespace cosim::testing
