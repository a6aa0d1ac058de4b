#include "bench/runner.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "registered_backend.hpp"
#include "scratch_directory.hpp"

namespace cosim::bench {
namespace {

using cosim::testing::ScratchDirectory;
using testing::backend;

// A run of a shell command; the suite objects it points to outlive it.
struct ShellRun {
  Scenario scenario;
  BackendRuns backend;
  PlannedRun run;
  ShellRun(const std::filesystem::path& dir, const std::string& name, const std::string& command) {
    scenario.name = name;
    backend.backend = &testing::backend("coupler");
    run.scenario = &scenario;
    run.backend = &backend;
    run.directory = dir / name;
    std::filesystem::create_directories(run.directory);
    run.executable = "/bin/sh";
    run.args = {"-c", command};
    run.key = "key-" + name;
  }
};

TEST(Runner, RunsRecordsAndResumesWithoutRepeatingFinishedRuns) {
  ScratchDirectory dir;
  const auto counter = dir.path() / "count";
  ShellRun ok(dir.path(), "ok", "echo x >> " + counter.string());
  ShellRun bad(dir.path(), "bad", "echo 'FATAL: no mesh' >&2; exit 3");
  std::vector<PlannedRun> runs{ok.run, bad.run};
  auto records = run_all(runs, {2, false, nullptr});
  ASSERT_EQ(records.size(), 2u);
  EXPECT_TRUE(records[0].completed());
  EXPECT_EQ(records[1].state, "failed");
  EXPECT_EQ(records[1].exit_code, 3);
  EXPECT_NE(records[1].message.find("FATAL: no mesh"), std::string::npos) << records[1].message;
  EXPECT_EQ(read_record(runs[1]).state, "failed");

  // Again: the finished run is kept, the failed one tried again.
  records = run_all(runs, {1, false, nullptr});
  EXPECT_TRUE(records[0].reused);
  EXPECT_FALSE(records[1].reused);
  std::ifstream in(counter);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, 1);

  // Changed inputs (another key) run again.
  runs[0].key = "changed";
  records = run_all(runs, {1, false, nullptr});
  EXPECT_FALSE(records[0].reused);
  EXPECT_TRUE(records[0].completed());
}

TEST(Runner, AnInterruptStopsTheRunsAndRecordsThem) {
  ScratchDirectory dir;
  ShellRun slow(dir.path(), "slow", "sleep 30");
  ShellRun next(dir.path(), "next", "true");
  std::atomic<bool> interrupted{false};
  std::thread stop([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    interrupted = true;
  });
  const auto start = std::chrono::steady_clock::now();
  const auto records = run_all({slow.run, next.run}, {1, false, &interrupted});
  stop.join();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_EQ(records[0].state, "interrupted");
  EXPECT_EQ(records[1].state, "interrupted");
}

TEST(Runner, AProgramThatCannotBeFoundIsAFailedRun) {
  ScratchDirectory dir;
  ShellRun missing(dir.path(), "missing", "");
  missing.run.executable = "no_such_solver_anywhere";
  const auto records = run_all({missing.run}, {1, false, nullptr});
  EXPECT_EQ(records[0].state, "failed");
  EXPECT_NE(records[0].message.find("no_such_solver_anywhere"), std::string::npos);
}

}  // namespace
}  // namespace cosim::bench
