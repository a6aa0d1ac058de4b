// The promises of `cosim run` and `cosim validate` on absurd or hostile
// input (architecture.md §6): a located message and exit 2 for bad input, timeouts
// passed down and kept to a sane range, runs never mixed in one directory,
// participant configs checked by `cosim validate`, signals obeyed in every
// wait, and nothing of a killed coupler left behind.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "demo_job.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(RunContract, ConnectTimeoutIsPassedToParticipantsAndKeptInRange) {
  const fs::path dir = fresh_directory("contract_connect_timeout");
  const fs::path job = write_job(dir, {});
  const auto r = cosim_run(job, dir / "run", 120, {"--connect-timeout", "7"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(read_text(dir / "run" / "log.txt"), HasSubstr("--cosim-connect-timeout 7"));
  for (const char* absurd : {"1e10", "0", "-1", "nan"}) {
    const auto bad =
        cosim_run(job, dir / ("run_" + std::string(absurd)), 30, {"--connect-timeout", absurd});
    EXPECT_EQ(bad.exit_code, 2) << absurd << ": " << bad.output;
    EXPECT_THAT(bad.output, HasSubstr("--connect-timeout"));
  }
}

TEST(RunContract, AnAbsurdWindowTimeoutIsRefusedWithItsLine) {
  const fs::path dir = fresh_directory("contract_window_timeout");
  JobOptions o;
  o.window_timeout = 1e300;
  const auto r = cosim_run(write_job(dir, o), dir / "run", 30);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("job.yaml:8:"));
  EXPECT_THAT(r.output, HasSubstr("window_timeout"));
}

// ZeroMQ binds an interface's address: the names of loopback are taken too.
TEST(RunContract, LoopbackByNameOrIpv6Binds) {
  const fs::path dir = fresh_directory("contract_hosts");
  JobOptions o;
  o.scheme = "tcp";
  o.host = "localhost";
  const auto by_name = cosim_run(write_job(dir, o), dir / "run_localhost");
  EXPECT_EQ(by_name.exit_code, 0) << by_name.output;
  o.host = "::1";
  const auto ipv6 = cosim_run(write_job(dir, o), dir / "run_ipv6");
  const bool has_ipv6_loopback =
      read_text("/proc/net/if_inet6").find("00000000000000000000000000000001") != std::string::npos;
  if (has_ipv6_loopback) {
    EXPECT_EQ(ipv6.exit_code, 0) << ipv6.output;
    EXPECT_THAT(read_text(dir / "run_ipv6" / "log.txt"), HasSubstr("tcp://[::1]:"));
  } else {
    EXPECT_EQ(ipv6.exit_code, 2) << ipv6.output;
    EXPECT_THAT(ipv6.output, HasSubstr("zmq.host"));
  }
}

TEST(RunContract, HugeNamesAndPathsAreBadInput) {
  const fs::path dir = fresh_directory("contract_huge");
  const std::string job = read_text(write_job(dir, {}));
  const std::string huge(2 * 1024 * 1024, 'a');  // beyond any kernel limit on an argument
  write_text(dir / "name.yaml", replaced(job, "name: e2e", "name: " + huge));
  write_text(dir / "config.yaml", replaced(job, "config: left.yaml", "config: " + huge + ".yaml"));
  write_text(dir / "participant.yaml", replaced(replaced(job, "  left:\n", "  " + huge + ":\n"),
                                                "from: left", "from: " + huge));
  for (const char* file : {"name.yaml", "config.yaml", "participant.yaml"}) {
    for (const char* command : {"validate", "run"}) {
      std::vector<std::string> args{binary("cosim").string(), command, (dir / file).string()};
      if (std::string(command) == "run")
        args.insert(args.end(), {"--output", (dir / "run").string()});
      const auto r = run(args, std::chrono::seconds(60));
      const std::string head = r.output.substr(0, 1000);
      EXPECT_EQ(r.exit_code, 2) << command << " " << file << ": " << head;
      EXPECT_THAT(head, HasSubstr(file)) << command << " " << file;
      EXPECT_LT(r.output.size(), 10000u) << "the message repeats the huge value: " << head;
    }
  }
  // A long path on the command line (the kernel passes up to 128 KiB).
  const std::string long_path = (dir / std::string(100 * 1024, 'b')).string() + ".yaml";
  const auto r = run({binary("cosim").string(), "validate", long_path}, std::chrono::seconds(30));
  EXPECT_EQ(r.exit_code, 2) << r.output.substr(0, 2000);
}

TEST(RunContract, ANonEmptyOutputDirectoryIsRefusedUnlessOverwritten) {
  const fs::path dir = fresh_directory("contract_output_reuse");
  JobOptions o;
  o.end_time = 0.025;
  const fs::path job = write_job(dir, o);
  ASSERT_EQ(cosim_run(job, dir / "run").exit_code, 0);
  const std::string first_summary = read_text(dir / "run" / "summary.json");
  write_text(dir / "run" / "left" / "stale_snapshot.h5", "from a longer run");

  const auto again = cosim_run(job, dir / "run");
  EXPECT_EQ(again.exit_code, 2) << again.output;
  EXPECT_THAT(again.output, HasSubstr("--overwrite"));
  EXPECT_EQ(read_text(dir / "run" / "summary.json"), first_summary) << "the refusal touched it";

  const auto overwritten = cosim_run(job, dir / "run", 120, {"--overwrite"});
  EXPECT_EQ(overwritten.exit_code, 0) << overwritten.output;
  EXPECT_FALSE(fs::exists(dir / "run" / "left" / "stale_snapshot.h5"));
  EXPECT_EQ(read_csv(dir / "run" / "right" / "temperature_read.csv").size(), 10u);

  // --overwrite never empties a directory that is not an earlier run's.
  fs::create_directories(dir / "precious");
  write_text(dir / "precious" / "thesis.tex", "years of work");
  const auto refused = cosim_run(job, dir / "precious", 30, {"--overwrite"});
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_TRUE(fs::exists(dir / "precious" / "thesis.tex"));
}

TEST(RunContract, ValidateChecksEveryParticipantConfig) {
  const fs::path dir = fresh_directory("contract_validate");
  const fs::path job = write_job(dir, {});
  const auto good =
      run({binary("cosim").string(), "validate", job.string()}, std::chrono::seconds(30));
  EXPECT_EQ(good.exit_code, 0) << good.output;
  EXPECT_THAT(good.output, HasSubstr("left"));
  EXPECT_THAT(good.output, HasSubstr("is valid"));

  write_text(dir / "right.yaml", read_text(dir / "right.yaml") + "surprise_key: 1\n");
  const auto bad =
      run({binary("cosim").string(), "validate", job.string()}, std::chrono::seconds(30));
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_THAT(bad.output, HasSubstr("right.yaml:"));
  EXPECT_THAT(bad.output, HasSubstr("surprise_key"));
  EXPECT_THAT(bad.output, HasSubstr("not valid"));
}

// A participant program that never answers `--validate`: cosim validate
// waits for it, and a signal ends the wait at once, taking it along.
TEST(RunContract, ValidateStopsOnASignal) {
  const fs::path dir = fresh_directory("contract_validate_signal");
  const fs::path job = write_job(dir, {});
  write_text(dir / "sleeper.sh",
             "#!/bin/sh\necho $$ > " + (dir / "sleeper.pid").string() + "\nexec sleep 600\n");
  fs::permissions(dir / "sleeper.sh", fs::perms::owner_all);
  write_text(job, replaced(read_text(job), "executable: cosim_test_participant",
                           "executable: ./sleeper.sh"));
  const pid_t validate =
      spawn({binary("cosim").string(), "validate", job.string()}, dir / "validate.log");
  const pid_t sleeper = wait_for_pid_file(dir / "sleeper.pid", std::chrono::seconds(30));
  const auto start = Clock::now();
  ASSERT_EQ(::kill(validate, SIGTERM), 0);
  const auto r = wait_for(validate, dir / "validate.log", std::chrono::seconds(30));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_THAT(r.output, HasSubstr("signal 15"));
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 5.0);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(process_exists(sleeper));
}

// The private ipc directory of a coupler killed by SIGKILL is removed by the
// next coupler that starts.
TEST(RunContract, AKilledCouplersIpcDirectoryIsCleanedAtTheNextStart) {
  const fs::path dir = fresh_directory("contract_stale_ipc");
  JobOptions o;
  o.end_time = 1000.0;
  const fs::path job = write_job(dir, o);
  const pid_t cosim =
      spawn({binary("cosim").string(), "run", job.string(), "--output", (dir / "killed").string()},
            dir / "killed.log");
  wait_for_pid_file(dir / "killed" / "right" / "pid", std::chrono::seconds(30));
  const std::string log = read_text(dir / "killed" / "log.txt");
  const auto at = log.find("ipc://");
  ASSERT_NE(at, std::string::npos) << log;
  const fs::path socket = log.substr(at + 6, log.find_first_of(" \n", at) - at - 6);
  const fs::path private_dir = socket.parent_path();
  ASSERT_TRUE(fs::exists(private_dir));
  ::kill(cosim, SIGKILL);
  wait_for(cosim, dir / "killed.log", std::chrono::seconds(10));
  EXPECT_TRUE(fs::exists(private_dir)) << "nothing to clean";

  o.end_time = 0.01;
  const auto next = cosim_run(write_job(dir, o), dir / "next");
  EXPECT_EQ(next.exit_code, 0) << next.output;
  EXPECT_FALSE(fs::exists(private_dir));
  EXPECT_THAT(read_text(dir / "next" / "log.txt"), HasSubstr(private_dir.string()));
}

}  // namespace
}  // namespace cosim::testing

namespace cosim::testing {
namespace {

// A solver running on its own: SIGTERM (as `cosim` stops its participants,
// or Ctrl-C) ends it between steps, with its summary.json finished saying
// why, instead of killing it with its record "running".
struct LongCase {
  const char* solver;
  const char* config;
  const char* end_time_from;
  const char* end_time_to;
};

void PrintTo(const LongCase& c, std::ostream* out) {
  *out << c.solver << " on " << c.config;
}

class SolverStops : public ::testing::TestWithParam<LongCase> {};

TEST_P(SolverStops, OnASignalBetweenStepsWithItsRecord) {
  const LongCase& c = GetParam();
  const fs::path dir = fresh_directory(std::string("solver_stop_") + c.solver);
  const fs::path shipped = fs::path(COSIM_SOURCE_DIR) / "configs" / c.config;
  write_text(dir / "case.yaml", replaced(read_text(shipped), c.end_time_from, c.end_time_to));
  for (const auto& entry : fs::directory_iterator(shipped.parent_path()))
    if (entry.path().extension() != ".yaml" && entry.is_regular_file())
      fs::copy_file(entry.path(), dir / entry.path().filename(),
                    fs::copy_options::overwrite_existing);
  const pid_t solver = spawn({binary(c.solver).string(), "--config", (dir / "case.yaml").string(),
                              "--output", (dir / "run").string()},
                             dir / "console.log");
  // Stepping: its summary.json exists and it has written its first output.
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (!fs::exists(dir / "run" / "summary.json") && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const auto start = Clock::now();
  ASSERT_EQ(::kill(solver, SIGTERM), 0);
  const auto r = wait_for(solver, dir / "console.log", std::chrono::seconds(60));
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::printf("%s: exit %d %.2f s after SIGTERM\n", c.solver, r.exit_code, seconds);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_LT(seconds, 10.0);
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_EQ(summary["status"]["state"], "finished");
  EXPECT_THAT(summary["status"]["message"].get<std::string>(), HasSubstr("stopped by signal 15"));
}

INSTANTIATE_TEST_SUITE_P(Reliability, SolverStops,
                         ::testing::Values(LongCase{"swe_fluid", "swe/stoker_dam_break.yaml",
                                                    "end_time: 0.1", "end_time: 1.0e4"},
                                           LongCase{"mpm_solver", "mpm/elastic_block_drop.yaml",
                                                    "end_time: 0.5", "end_time: 100.0"},
                                           LongCase{"ice_fluid", "ice/martin_moyce.yaml",
                                                    "end_time: 0.19", "end_time: 1.0e4"}),
                         [](const ::testing::TestParamInfo<LongCase>& param_info) {
                           return std::string(param_info.param.solver);
                         });

}  // namespace
}  // namespace cosim::testing
