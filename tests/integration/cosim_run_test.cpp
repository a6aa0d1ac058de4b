// End to end: `cosim run` with two test participants whose time steps (1e-3 s
// and 7e-4 s) do not divide the 2.5e-3 s window, on different grids.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <thread>

#include "demo_job.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// What the writer integrated over window k is what the reader applied, over
// its own sub-steps, in window k + 1.
void expect_window_integrals_conserved(const fs::path& run_dir, std::size_t windows) {
  const auto sent = read_csv(run_dir / "left" / "heat_sent.csv");
  const auto applied = read_csv(run_dir / "right" / "heat_applied.csv");
  ASSERT_EQ(sent.size(), windows);
  ASSERT_EQ(applied.size(), windows);
  EXPECT_EQ(applied[0][2], 0.0);  // nothing had been sent before the first window
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < windows; ++k) {
    EXPECT_DOUBLE_EQ(sent[k][1], applied[k][1]) << "window end times differ at window " << k + 1;
    const double error = std::abs(applied[k + 1][2] - sent[k][2]) / std::abs(sent[k][2]);
    worst = std::max(worst, error);
  }
  std::printf("window integral: max relative difference sent vs applied = %.3e\n", worst);
  EXPECT_LE(worst, 1e-12);
}

TEST(CosimRun, DemoJobOverZmqIpcMapsAndConserves) {
  const fs::path dir = fresh_directory("e2e_ipc");
  const auto r = cosim_run(write_job(dir, {}), dir / "run");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_window_integrals_conserved(dir / "run", 20);
  // The reader checks the consistent map of the linear temperature itself
  // (and would have failed the run); its log shows the error it measured.
  const auto reads = read_csv(dir / "run" / "right" / "temperature_read.csv");
  ASSERT_EQ(reads.size(), 20u);
  for (const auto& row : reads) EXPECT_LE(row[3], 0.26);
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 0);
  EXPECT_EQ(summary["windows"], 20);
  EXPECT_LE(summary["metrics"]["max_conservative_mapping_error"]["value"].get<double>(), 1e-12);
  EXPECT_TRUE(summary["wall_time_s"]["phases"].contains("mapping"));
  EXPECT_TRUE(fs::exists(dir / "run" / "log.txt"));
}

TEST(CosimRun, DemoJobOverZmqTcpLoopback) {
  const fs::path dir = fresh_directory("e2e_tcp");
  JobOptions o;
  o.scheme = "tcp";
  const auto r = cosim_run(write_job(dir, o), dir / "run");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_window_integrals_conserved(dir / "run", 20);
  EXPECT_THAT(read_text(dir / "run" / "log.txt"), HasSubstr("tcp://127.0.0.1:"));
}

TEST(CosimRun, DemoJobOverMpiUnderOneMpmdLaunch) {
  const fs::path dir = fresh_directory("e2e_mpi");
  JobOptions o;
  o.transport = "mpi";
  const auto job = write_job(dir, o);
  const auto printed = run({binary("cosim").string(), "run", job.string(), "--output",
                            (dir / "run").string(), "--print-mpi-command"},
                           std::chrono::seconds(30));
  ASSERT_EQ(printed.exit_code, 0) << printed.output;
  EXPECT_THAT(printed.output, HasSubstr("mpirun"));
  EXPECT_THAT(printed.output, HasSubstr(" : -np 1 "));
  EXPECT_THAT(printed.output, HasSubstr("--cosim-endpoint mpi://"));

  const auto r = cosim_run(job, dir / "run", 300);
  ASSERT_EQ(r.exit_code, 0) << r.output << read_text(dir / "run" / "mpirun.log");
  expect_window_integrals_conserved(dir / "run", 20);
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_EQ(summary["job"]["transport"], "mpi");
}

// `--slurm-script` writes the batch script and its multi-prog file of an MPI
// job, runs nothing and prepares no output directory; a ZeroMQ job has no
// MPMD launch to write (exit 2).
TEST(CosimRun, SlurmScriptOfAnMpiJobIsWrittenAndNothingRuns) {
  const fs::path dir = fresh_directory("e2e_slurm");
  JobOptions o;
  o.transport = "mpi";
  const auto job = write_job(dir, o);
  const fs::path script = dir / "run.slurm";
  const std::vector<std::string> args{
      binary("cosim").string(), "run",          job.string(), "--output", (dir / "run").string(),
      "--slurm-script",         script.string()};
  const auto r = run(args, std::chrono::seconds(30));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("sbatch " + script.string()));
  EXPECT_THAT(read_text(script), HasSubstr("#SBATCH --ntasks=3\n"));
  const std::string conf = read_text(script.string() + ".multi-prog.conf");
  EXPECT_THAT(conf, HasSubstr("\n0 env COSIM_APP_INDEX=0 " + binary("cosim").string() + " run "));
  EXPECT_THAT(conf, HasSubstr("\n2 env COSIM_APP_INDEX=2 "));
  EXPECT_FALSE(fs::exists(dir / "run"));

  const auto again = run(args, std::chrono::seconds(30));
  EXPECT_EQ(again.exit_code, 2) << again.output;
  EXPECT_THAT(again.output, HasSubstr("--overwrite"));
}

TEST(CosimRun, SlurmScriptOfAZmqJobIsRefusedWithExit2) {
  const fs::path dir = fresh_directory("e2e_slurm_zmq");
  const auto job = write_job(dir, {});
  const auto r = run({binary("cosim").string(), "run", job.string(), "--output",
                      (dir / "run").string(), "--slurm-script", (dir / "run.slurm").string()},
                     std::chrono::seconds(30));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--slurm-script needs 'transport: mpi'"));
  EXPECT_FALSE(fs::exists(dir / "run.slurm"));
  EXPECT_FALSE(fs::exists(dir / "run"));
}

// A run that would last long (end time 1000 s), started in the background,
// with both participants up.
struct LongRun {
  fs::path dir;
  fs::path log;
  pid_t cosim = 0;
  pid_t left = 0;
  pid_t right = 0;
};

LongRun start_long_run(const std::string& name) {
  LongRun run;
  run.dir = fresh_directory(name);
  JobOptions o;
  o.end_time = 1000.0;
  const auto job = write_job(run.dir, o);
  run.log = run.dir / "cosim.log";
  run.cosim =
      spawn({binary("cosim").string(), "run", job.string(), "--output", (run.dir / "run").string()},
            run.log);
  run.left = wait_for_pid_file(run.dir / "run" / "left" / "pid", std::chrono::seconds(30));
  run.right = wait_for_pid_file(run.dir / "run" / "right" / "pid", std::chrono::seconds(30));
  return run;
}

TEST(CosimRun, KilledParticipantEndsTheRunWithExit3AndNoOrphans) {
  const LongRun run = start_long_run("e2e_kill");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // mid-run
  ASSERT_EQ(::kill(run.right, SIGKILL), 0);
  const auto r = wait_for(run.cosim, run.log, std::chrono::seconds(60));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participant 'right'"));
  EXPECT_THAT(r.output, HasSubstr("killed by signal 9"));
  EXPECT_FALSE(process_exists(run.left)) << "participant 'left' outlived the coupler";
  EXPECT_FALSE(process_exists(run.right));
  const auto summary = nlohmann::json::parse(read_text(run.dir / "run" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 3);
}

TEST(CosimRun, KilledCouplerTakesItsParticipantsWithIt) {
  const LongRun run = start_long_run("e2e_kill_coupler");
  ASSERT_EQ(::kill(run.cosim, SIGKILL), 0);
  wait_for(run.cosim, run.log, std::chrono::seconds(10));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while ((process_exists(run.left) || process_exists(run.right)) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(process_exists(run.left));
  EXPECT_FALSE(process_exists(run.right));
}

TEST(CosimRun, TerminatedCouplerStopsItsParticipantsAndRecordsWhy) {
  const LongRun run = start_long_run("e2e_sigterm");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(::kill(run.cosim, SIGTERM), 0);
  const auto r = wait_for(run.cosim, run.log, std::chrono::seconds(30));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_THAT(r.output, HasSubstr("interrupted by a signal"));
  EXPECT_FALSE(process_exists(run.left));
  EXPECT_FALSE(process_exists(run.right));
  const auto summary = nlohmann::json::parse(read_text(run.dir / "run" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 3);
}

// The participant's numerical failure (its exit 4) is cosim's exit 4, and
// the participant's own record is complete: it was let finish before the
// others were stopped.
TEST(CosimRun, FailingParticipantIsNamedWithItsReasonAndItsRecordKept) {
  const fs::path dir = fresh_directory("e2e_crash");
  JobOptions o;
  o.left_args = "[--crash-at-window, '3']";
  const auto r = cosim_run(write_job(dir, o), dir / "run");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participant 'left'"));
  EXPECT_THAT(r.output, HasSubstr("crash requested at window 3"));
  const auto left = nlohmann::json::parse(read_text(dir / "run" / "left" / "summary.json"));
  EXPECT_EQ(left["status"]["state"], "finished");
  EXPECT_EQ(left["status"]["exit_code"], 4);
  EXPECT_THAT(read_text(dir / "run" / "left" / "console.log"),
              HasSubstr("crash requested at window 3"));
  const auto right = nlohmann::json::parse(read_text(dir / "run" / "right" / "summary.json"));
  EXPECT_EQ(right["status"]["state"], "finished");
}

TEST(CosimRun, HungParticipantTimesOutWithExit3) {
  const fs::path dir = fresh_directory("e2e_hang");
  JobOptions o;
  o.window_timeout = 2.0;
  o.right_args = "[--hang-at-window, '2']";
  const auto start = std::chrono::steady_clock::now();
  const auto r = cosim_run(write_job(dir, o), dir / "run");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_THAT(r.output, HasSubstr("window 2 from 'right'"));
  EXPECT_LT(seconds, 30.0);
  const pid_t right = wait_for_pid_file(dir / "run" / "right" / "pid", std::chrono::seconds(1));
  EXPECT_FALSE(process_exists(right));
}

// A field linear in time and constant in space (so mapping is exact): with
// linear extrapolation the reader sees its exact value at every sub-step
// once two windows of history have arrived; held constant it lags.
void write_time_linear_fields(const fs::path& dir) {
  write_text(dir / "left.yaml", R"(kind: test_participant
dt: 1.0e-3
mesh: {dim: 2, origin: [0.0, 0.0], spacing: [0.1, 0.1], cells: [20, 10]}
writes:
  - {name: temperature, unit: K, function: [300.0, 0.0, 0.0, 0.0, 10.0]}
  - {name: heat, unit: J, quantity: extensive, time: integral}
reads:
  - {name: pressure, unit: Pa}
)");
  write_text(dir / "right.yaml", R"(kind: test_participant
dt: 7.0e-4
mesh: {dim: 2, origin: [0.1, 0.1], spacing: [0.14, 0.12], cells: [13, 6], location: node}
writes:
  - {name: pressure, unit: Pa}
reads:
  - {name: temperature, unit: K, function: [300.0, 0.0, 0.0, 0.0, 10.0], tolerance: 1.0e-9,
     check_every_step_from_window: 3}
  - {name: heat, unit: J, quantity: extensive, time: integral}
)");
}

TEST(CosimRun, LinearExtrapolationIsExactForFieldsLinearInTime) {
  const fs::path dir = fresh_directory("e2e_extrapolation");
  JobOptions o;
  o.extrapolation = "linear";
  const auto job = write_job(dir, o);
  write_time_linear_fields(dir);
  const auto r = cosim_run(job, dir / "run");
  EXPECT_EQ(r.exit_code, 0) << r.output;

  o.extrapolation = "constant";  // the control: the held value lags by up to 10 K/s x window
  const auto held = write_job(dir, o);
  write_time_linear_fields(dir);
  const auto lagging = cosim_run(held, dir / "run_constant");
  EXPECT_EQ(lagging.exit_code, 4);  // the reader's numerical failure, passed through
  EXPECT_THAT(lagging.output, HasSubstr("read 'temperature'"));
}

TEST(CosimRun, BadInputExitsWith2AndNamesIt) {
  const fs::path dir = fresh_directory("e2e_bad_input");
  std::string job = read_text(write_job(dir, {}));
  job.replace(job.find("executable: cosim_test_participant"),
              std::string("executable: cosim_test_participant").size(),
              "executable: no_such_solver");
  write_text(dir / "job.yaml", job);
  const auto missing = cosim_run(dir / "job.yaml", dir / "run");
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_THAT(missing.output, HasSubstr("'no_such_solver'"));

  const auto no_output =
      run({binary("cosim").string(), "run", (dir / "job.yaml").string()}, std::chrono::seconds(30));
  EXPECT_EQ(no_output.exit_code, 2) << no_output.output;
  EXPECT_THAT(no_output.output, HasSubstr("--output"));

  const auto no_file = run({binary("cosim").string(), "validate", (dir / "nope.yaml").string()},
                           std::chrono::seconds(30));
  EXPECT_EQ(no_file.exit_code, 2);
  EXPECT_THAT(no_file.output, HasSubstr("nope.yaml"));
}

}  // namespace
}  // namespace cosim::testing
