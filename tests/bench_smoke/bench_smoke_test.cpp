// `cosim bench` end to end on a shipped suite (configs/bench/<suite>.yaml) at
// the coarse resolution (--resolution full with -DCOSIM_FULL_VALIDATION=ON):
// every run finishes, results.csv holds exactly the rows the suite asks for
// (scenario x backend x level x metric), every metric with a tolerance is
// within it and every other metric with a reference has its error, and
// report.md has a section and the plots of every scenario. The errors are
// printed next to their tolerances.
//
// The suite's name is the first argument. Without OpenFOAM, a suite that
// needs it exits 77, which CTest reports as not run (SKIP_RETURN_CODE).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "bench/suite.hpp"
#include "cosim/error.hpp"
#include "cosim/io/csv_table.hpp"
#include "openfoam/foam/installation.hpp"
#include "run_process.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;
using bench::Resolution;

std::string suite_name;

#ifdef COSIM_FULL_VALIDATION
constexpr Resolution resolution = Resolution::full;
#else
constexpr Resolution resolution = Resolution::coarse;
#endif

using Row = std::tuple<std::string, std::string, std::string, std::string>;

// The rows the suite asks for at this resolution.
std::set<Row> expected_rows(const bench::Suite& suite) {
  std::set<Row> rows;
  for (const auto& s : suite.scenarios) {
    for (const auto& b : s.backends) {
      std::vector<std::string> levels;
      for (const auto& l : b.levels)
        if (!l.only || *l.only == resolution) levels.push_back(l.label);
      if (b.levels.empty()) levels.emplace_back();
      for (const auto& level : levels)
        for (const auto& m : s.metrics)
          if (!m.resolution || *m.resolution == resolution)
            rows.insert({s.name, b.backend->name, level, m.name});
    }
  }
  return rows;
}

TEST(BenchSmoke, TheSuitesReportHasEveryRowWithinTolerance) {
  const fs::path suite_file =
      fs::path(COSIM_SOURCE_DIR) / "configs" / "bench" / (suite_name + ".yaml");
  const bench::Suite suite = bench::load_suite(suite_file);
  const fs::path out = fresh_directory("bench_smoke_" + suite_name);
  const ProcessResult r = run({binary("cosim").string(), "bench", suite_file.string(), "--output",
                               out.string(), "--resolution", bench::to_string(resolution)},
                              std::chrono::seconds(7200));
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const auto table = CsvTable::read(out / "results.csv");
  const auto column = [&](std::size_t row, const char* name) {
    return table.text(row, table.index(name));
  };
  std::set<Row> rows;
  fmt::print("{:<28} {:<9} {:<11} {:<22} {:>12} {:>12}  {}\n", "scenario", "backend", "level",
             "metric", "error", "tolerance", "verdict");
  for (std::size_t i = 0; i < table.rows(); ++i) {
    rows.insert(
        {column(i, "scenario"), column(i, "backend"), column(i, "level"), column(i, "metric")});
    const std::string verdict = column(i, "verdict");
    fmt::print("{:<28} {:<9} {:<11} {:<22} {:>12} {:>12}  {}\n", column(i, "scenario"),
               column(i, "backend"), column(i, "level"), column(i, "metric"), column(i, "error"),
               column(i, "tolerance"), verdict);
    const std::string what =
        fmt::format("{} / {} {} / {}", column(i, "scenario"), column(i, "backend"),
                    column(i, "level"), column(i, "metric"));
    EXPECT_EQ(column(i, "run_state"), "completed") << what;
    if (!column(i, "tolerance").empty()) {
      EXPECT_EQ(verdict, "pass") << what << ": " << column(i, "note");
    }
    if (!column(i, "reference_label").empty()) {
      EXPECT_TRUE(std::isfinite(table.row(i)[table.index("error")])) << what;
    }
    EXPECT_NE(verdict, "unavailable") << what << ": " << column(i, "note");
  }
  EXPECT_EQ(rows, expected_rows(suite));
  EXPECT_EQ(rows.size(), table.rows()) << "a row twice";

  std::ifstream report(out / "report.md");
  std::stringstream text;
  text << report.rdbuf();
  for (const auto& s : suite.scenarios) {
    EXPECT_NE(text.str().find("## " + s.title), std::string::npos) << s.name;
    const fs::path wall_time = out / "plots" / (s.name + "__wall_time.png");
    EXPECT_TRUE(fs::exists(wall_time)) << wall_time;
  }
}

bool needs_openfoam(const bench::Suite& suite) {
  for (const auto& s : suite.scenarios)
    for (const auto& b : s.backends)
      if (b.backend->name == "openfoam") return true;
  return false;
}

}  // namespace
}  // namespace cosim::testing

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (argc < 2) {
    fmt::print(stderr, "usage: bench_smoke_test <suite name in configs/bench>\n");
    return 2;
  }
  cosim::testing::suite_name = argv[1];
  try {
    const auto suite =
        cosim::bench::load_suite(std::filesystem::path(COSIM_SOURCE_DIR) / "configs" / "bench" /
                                 (cosim::testing::suite_name + ".yaml"));
    if (cosim::testing::needs_openfoam(suite))
      openfoam::find_installation(
          {"interFoam", "MPPICInterFoam", "blockMesh", "setFields", "postProcess"});
  } catch (const cosim::Error& e) {
    fmt::print("suite '{}' needs OpenFOAM, which is not installed, so this test does not run: {}\n",
               cosim::testing::suite_name, e.what());
    return 77;
  }
  return RUN_ALL_TESTS();
}
