// Fault injection: participants killed, stopped or crashing at start-up,
// mid-run and after the last window, and `cosim` itself signalled at each
// phase, over ZeroMQ and MPI. Every case must end with the promised exit
// code within a bounded time, name the participant at fault, leave a
// finished summary.json, and leave no process behind.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

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
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr double window_timeout_s = 2.0;
constexpr double connect_timeout_s = 2.0;
// What a fault may take beyond the timeout that detects it: the grace the
// participants get to finish their records (3 s), then to stop (3 s), and
// process start-up.
constexpr double detection_slack_s = 10.0;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The state letter of /proc/<pid>/stat ('T' when stopped), or 0.
char process_state(pid_t pid) {
  std::ifstream in(fmt::format("/proc/{}/stat", pid));
  std::string stat;
  if (!std::getline(in, stat)) return 0;
  const auto end = stat.rfind(')');
  return end == std::string::npos || end + 2 >= stat.size() ? 0 : stat[end + 2];
}

void wait_until_stopped(pid_t pid, std::chrono::seconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (process_state(pid) != 'T' && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(process_state(pid), 'T') << "process " << pid << " did not stop";
}

// Neither participant (pids from their pid files) is left, zombies aside.
void expect_no_process_left(const fs::path& run) {
  for (const char* name : {"left", "right"}) {
    std::ifstream in(run / name / "pid");
    pid_t pid = 0;
    if (!(in >> pid)) continue;  // it never got that far
    const auto deadline = Clock::now() + std::chrono::seconds(5);
    while (process_exists(pid) && process_state(pid) != 'Z' && Clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_TRUE(!process_exists(pid) || process_state(pid) == 'Z')
        << "participant '" << name << "' (pid " << pid << ") outlived the run";
  }
}

nlohmann::json summary_of(const fs::path& run) {
  return nlohmann::json::parse(read_text(run / "summary.json"));
}

void expect_finished_with(const fs::path& run, int exit_code) {
  const auto summary = summary_of(run);
  EXPECT_EQ(summary["status"]["state"], "finished");
  EXPECT_EQ(summary["status"]["exit_code"], exit_code) << summary["status"].dump();
}

// ---------------------------------------------------------------------------
// A participant sends itself a signal at one phase of the run.

struct ParticipantFault {
  std::string transport;    // zmq | mpi
  std::string participant;  // left | right
  std::string signal;       // SIGKILL | SIGSTOP | SIGSEGV
  std::string phase;        // startup | window:3 | end
};

void PrintTo(const ParticipantFault& f, std::ostream* out) {
  *out << f.transport << " " << f.participant << " " << f.signal << " at " << f.phase;
}

std::string name_of(const ::testing::TestParamInfo<ParticipantFault>& info) {
  const auto& f = info.param;
  std::string phase = f.phase.substr(0, f.phase.find(':'));
  return fmt::format("{}_{}_{}_{}", f.transport, f.participant, f.signal.substr(3), phase);
}

class ParticipantFaults : public ::testing::TestWithParam<ParticipantFault> {};

TEST_P(ParticipantFaults, EndTheRunWithExit3NamingItAndNothingLeft) {
  const ParticipantFault& f = GetParam();
  const fs::path dir = fresh_directory("fault_" + name_of({f, 0}));
  JobOptions o;
  o.transport = f.transport;
  o.window_timeout = window_timeout_s;
  const std::string args = fmt::format("[--raise, {}, --raise-at, '{}']", f.signal, f.phase);
  (f.participant == "left" ? o.left_args : o.right_args) = args;
  const auto start = Clock::now();
  const auto r = cosim_run(write_job(dir, o), dir / "run", 120,
                           {"--connect-timeout", fmt::format("{}", connect_timeout_s)});
  const double seconds = seconds_since(start);
  std::printf("%s: exit %d after %.2f s\n", name_of({f, 0}).c_str(), r.exit_code, seconds);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_THAT(r.output, HasSubstr("'" + f.participant + "'"));
  EXPECT_LT(seconds, std::max(window_timeout_s, connect_timeout_s) + detection_slack_s);
  expect_finished_with(dir / "run", 3);
  expect_no_process_left(dir / "run");
}

std::vector<ParticipantFault> participant_faults() {
  std::vector<ParticipantFault> faults;
  for (const char* transport : {"zmq", "mpi"})
    for (const char* participant : {"left", "right"})
      for (const char* signal : {"SIGKILL", "SIGSTOP", "SIGSEGV"})
        for (const char* phase : {"startup", "window:3", "end"})
          faults.push_back({transport, participant, signal, phase});
  return faults;
}

INSTANTIATE_TEST_SUITE_P(Reliability, ParticipantFaults, ::testing::ValuesIn(participant_faults()),
                         name_of);

// ---------------------------------------------------------------------------
// `cosim` receives SIGTERM, SIGINT or SIGHUP while it admits the
// participants, mid-run, and while it waits for them after the last window.

struct CouplerSignal {
  std::string transport;
  int signal;
  std::string phase;  // admission | mid_run | after_last_window
};

void PrintTo(const CouplerSignal& c, std::ostream* out) {
  *out << c.transport << " signal " << c.signal << " in " << c.phase;
}

std::string name_of_signal(const ::testing::TestParamInfo<CouplerSignal>& info) {
  const auto& s = info.param;
  const char* signal = s.signal == SIGTERM ? "TERM" : s.signal == SIGINT ? "INT" : "HUP";
  return fmt::format("{}_{}_{}", s.transport, signal, s.phase);
}

class CouplerSignals : public ::testing::TestWithParam<CouplerSignal> {};

TEST_P(CouplerSignals, StopTheRunWithExit3AndAFinishedRecord) {
  const CouplerSignal& c = GetParam();
  const fs::path dir = fresh_directory("signal_" + name_of_signal({c, 0}));
  JobOptions o;
  o.transport = c.transport;
  o.window_timeout = 60.0;  // long: the signal, not a timeout, must end the run
  if (c.phase == "admission") o.right_args = "[--raise, SIGSTOP, --raise-at, startup]";
  if (c.phase == "mid_run") o.end_time = 1000.0;
  if (c.phase == "after_last_window") o.right_args = "[--raise, SIGSTOP, --raise-at, end]";
  const fs::path job = write_job(dir, o);
  const fs::path log = dir / "cosim.log";
  const pid_t cosim = spawn({binary("cosim").string(), "run", job.string(), "--output",
                             (dir / "run").string(), "--connect-timeout", "60"},
                            log);
  const pid_t right = wait_for_pid_file(dir / "run" / "right" / "pid", std::chrono::seconds(30));
  if (c.phase == "mid_run") {
    wait_for_pid_file(dir / "run" / "left" / "pid", std::chrono::seconds(30));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  } else {
    wait_until_stopped(right, std::chrono::seconds(30));
  }
  const auto start = Clock::now();
  ASSERT_EQ(::kill(cosim, c.signal), 0);
  const auto r = wait_for(cosim, log, std::chrono::seconds(60));
  const double seconds = seconds_since(start);
  std::printf("%s: exit %d %.2f s after the signal\n", name_of_signal({c, 0}).c_str(), r.exit_code,
              seconds);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_THAT(r.output, HasSubstr("signal"));
  EXPECT_LT(seconds, detection_slack_s);
  expect_finished_with(dir / "run", 3);
  expect_no_process_left(dir / "run");
}

std::vector<CouplerSignal> coupler_signals() {
  std::vector<CouplerSignal> signals;
  for (const char* transport : {"zmq", "mpi"})
    for (int signal : {SIGTERM, SIGINT, SIGHUP})
      for (const char* phase : {"admission", "mid_run", "after_last_window"})
        signals.push_back({transport, signal, phase});
  return signals;
}

INSTANTIATE_TEST_SUITE_P(Reliability, CouplerSignals, ::testing::ValuesIn(coupler_signals()),
                         name_of_signal);

}  // namespace
}  // namespace cosim::testing
