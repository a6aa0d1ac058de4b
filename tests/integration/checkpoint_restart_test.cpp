// Checkpoint and restart of a coupled run (architecture.md §14) on test
// participants: `cosim run --checkpoint-every` writes whole checkpoints and
// keeps the last ones; `cosim run --restart` continues from one, and what
// the continued run writes equals, row for row and bit for bit, what the
// uninterrupted run wrote after the checkpoint, for an explicit scheme with
// linear extrapolation, an implicit scheme whose IQN-ILS reuses earlier
// windows' columns, and a stiff momentum exchange. A checkpoint of another
// job, with a truncated or missing file, or a participant that cannot take
// part, is refused with exit 2 saying which.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "demo_job.hpp"
#include "model_jobs.hpp"
#include "replaced_text.hpp"
#include "restart_continuation.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr int exit_bad_input = 2;

TEST(CheckpointRestart, AnExplicitRunWithLinearExtrapolationContinuesBitForBit) {
  const fs::path dir = fresh_directory("checkpoint_explicit");
  JobOptions o;
  o.extrapolation = "linear";
  const fs::path job = write_job(dir, o);
  expect_restart_continues(dir, job, "6", 12);
}

// IQN-ILS carries reused columns over the checkpoint, IQN-IMVJ its Jacobian.
TEST(CheckpointRestart, AnImplicitRunWithQuasiNewtonHistoryContinuesBitForBit) {
  for (const std::string method : {"iqn-ils", "iqn-imvj"}) {
    const fs::path dir = fresh_directory("checkpoint_implicit_" + method);
    write_fixed_point_case(dir, R"(coupling:
  scheme: parallel-implicit
  convergence:
    - {field: right.a, relative: 1.0e-10}
    - {field: left.b, relative: 1.0e-10}
  acceleration: {method: )" + method +
                                    R"(, reuse_windows: 4}
)");
    expect_restart_continues(dir, dir / "job.yaml", "3", 6);
    const auto whole = nlohmann::json::parse(read_text(dir / "whole" / "summary.json"));
    const auto continued = nlohmann::json::parse(read_text(dir / "continued" / "summary.json"));
    EXPECT_EQ(continued["coupling"]["windows"], whole["coupling"]["windows"]) << method;
    EXPECT_EQ(continued["coupling"]["iterations"], whole["coupling"]["iterations"]) << method;
  }
}

TEST(CheckpointRestart, AStiffMomentumExchangeContinuesBitForBitExplicitAndImplicit) {
  const fs::path explicit_dir = fresh_directory("checkpoint_drag_explicit");
  write_stiff_drag_case(explicit_dir, "");
  expect_restart_continues(explicit_dir, explicit_dir / "job.yaml", "0.03s", 3);
  const fs::path implicit_dir = fresh_directory("checkpoint_drag_implicit");
  write_stiff_drag_case(implicit_dir, R"(coupling:
  scheme: parallel-implicit
  convergence:
    - {field: water.momentum_exchange_impulse, relative: 1.0e-8}
    - {field: soil.momentum_exchange_impulse, relative: 1.0e-8}
)");
  expect_restart_continues(implicit_dir, implicit_dir / "job.yaml", "4", 4);
}

// The implicit energy exchange carries the heat applied in the last iterate
// over the checkpoint, as the momentum exchange its momentum.
TEST(CheckpointRestart, AStiffEnergyExchangeContinuesBitForBitImplicit) {
  const fs::path dir = fresh_directory("checkpoint_heat_implicit");
  write_stiff_heat_case(dir, R"(coupling:
  scheme: parallel-implicit
  convergence:
    - {field: water.heat_exchange_energy, relative: 1.0e-8}
    - {field: rock.heat_exchange_energy, relative: 1.0e-8}
)");
  expect_restart_continues(dir, dir / "job.yaml", "4", 4);
}

// swe_fluid over a bed a test participant raises: its solver state, output
// schedules and gauges continue from the checkpoint.
TEST(CheckpointRestart, ShallowWaterOverARisingBedContinuesBitForBit) {
  const fs::path dir = fresh_directory("checkpoint_swe");
  write_text(dir / "job.yaml", R"(kind: job
name: rising_bed
end_time: 0.4
window: 1.0e-2
participants:
  bed:
    executable: cosim_test_participant
    config: bed.yaml
    meshes: {grid: {kind: uniform_grid, dim: 1}}
    writes: {bed_elevation: grid}
    reads: {bed_traction: grid}
  water:
    executable: swe_fluid
    config: water.yaml
    meshes: {swe_cells: {kind: nonuniform_line, dim: 1}}
    writes: {bed_traction: swe_cells}
    reads: {bed_elevation: swe_cells}
exchange:
  - {from: bed, to: water, field: bed_elevation, mapping: consistent}
  - {from: water, to: bed, field: bed_traction, mapping: consistent}
)");
  write_text(dir / "bed.yaml", R"(kind: test_participant
dt: 4.0e-3
mesh: {dim: 1, origin: [0.0], spacing: [0.1], cells: [40]}
writes:
  - {name: bed_elevation, unit: m, function: [0.2, -0.04, 0.0, 0.0, 0.5]}
reads:
  - {name: bed_traction, unit: Pa, components: 2}
)");
  write_text(dir / "water.yaml", R"(kind: swe_case
name: tank
dimension: 1
mesh: {from: 0.0, to: 4.0, cells: 80}
physics: {manning: 0.01}
scheme: {flux: roe, limiter: van_leer, courant: 0.5}
initial: {free_surface: 0.5}
boundaries: {left: wall, right: wall}
time: {end_time: 0.4}
output:
  every: 0.05
  gauge_every: 0.01
  gauges:
    - {name: left, x: 0.5}
    - {name: right, x: 3.5}
coupling: {reads: [bed_elevation], writes: [bed_traction], bed_pressure: excess}
)");
  expect_restart_continues(dir, dir / "job.yaml", "10", 20);
}

// Zheng et al.'s clay column (configs/clay_still_water_Rws1.0*.yaml, to
// 0.06 s): mpm_solver and swe_fluid continue from a checkpoint, explicit
// and implicit (IQN-ILS reusing earlier windows' columns).
TEST(CheckpointRestart, TheClayColumnOnShallowWaterContinuesBitForBit) {
  const fs::path configs = fs::path(COSIM_SOURCE_DIR) / "configs";
  for (const char* file :
       {"clay_still_water_Rws1.0.yaml", "clay_still_water_Rws1.0_implicit.yaml"}) {
    const fs::path dir = fresh_directory(std::string("checkpoint_clay_") + file);
    std::string text = read_text(configs / file);
    text = replaced(text, "end_time: 5.0", "end_time: 0.06");
    text = replaced(text, "config: mpm/", fmt::format("config: {}/mpm/", configs.string()));
    text = replaced(text, "config: swe/", fmt::format("config: {}/swe/", configs.string()));
    write_text(dir / "job.yaml", text);
    expect_restart_continues(dir, dir / "job.yaml", "25", 25);
  }
}

// Terzaghi's column on ICE (configs/ice_coupled/terzaghi, while the load
// ramps up): ice_fluid and mpm_solver continue from a checkpoint, explicit
// and implicit.
TEST(CheckpointRestart, TheTerzaghiColumnOnIceContinuesBitForBit) {
  const fs::path case_dir = fs::path(COSIM_SOURCE_DIR) / "configs" / "ice_coupled" / "terzaghi";
  std::string text = read_text(case_dir / "job.yaml");
  text = replaced(text, "config: water.yaml", "config: " + (case_dir / "water.yaml").string());
  text = replaced(text, "config: soil.yaml", "config: " + (case_dir / "soil.yaml").string());
  const fs::path explicit_dir = fresh_directory("checkpoint_terzaghi_explicit");
  write_text(explicit_dir / "job.yaml", replaced(text, "end_time: 0.75", "end_time: 0.002"));
  expect_restart_continues(explicit_dir, explicit_dir / "job.yaml", "100", 100);
  const fs::path implicit_dir = fresh_directory("checkpoint_terzaghi_implicit");
  write_text(implicit_dir / "job.yaml",
             replaced(text, "end_time: 0.75", "end_time: 0.0006") +
                 "coupling:\n  scheme: parallel-implicit\n  max_iterations: 30\n" +
                 terzaghi_convergence + "  acceleration: {method: iqn-ils, reuse_windows: 4}\n");
  expect_restart_continues(implicit_dir, implicit_dir / "job.yaml", "30", 30);
}

TEST(CheckpointRestart, OnlyTheLastCheckpointsAreKeptAndEachIsComplete) {
  const fs::path dir = fresh_directory("checkpoint_kept");
  const fs::path job = write_job(dir, JobOptions{});
  const auto r = run_job(job, dir / "run", {"--checkpoint-every", "4"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // 20 windows: checkpoints after windows 4, 8, 12 and 16; the default keeps 2.
  EXPECT_EQ(checkpoints_in(dir / "run"),
            (std::vector<std::string>{"window_000000012", "window_000000016"}));
  const auto manifest =
      nlohmann::json::parse(read_text(checkpoint_of(dir / "run", 16) / "manifest.json"));
  EXPECT_EQ(manifest["kind"], "cosim_checkpoint");
  EXPECT_EQ(manifest["window"].get<int>(), 16);
  std::vector<std::string> files;
  for (const auto& f : manifest["files"]) files.push_back(f["path"].get<std::string>());
  EXPECT_EQ(files, (std::vector<std::string>{"coupler.h5", "left/participant.h5", "left/state.h5",
                                             "right/participant.h5", "right/state.h5"}));
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_EQ(summary["checkpoints"]["written"].get<int>(), 4);
}

// A batch system's wall-time limit: SIGTERM to `cosim run` makes it write a
// checkpoint at the next window end and stop (exit 5) with the participants
// ended normally; the run restarted from that checkpoint ends as an
// uninterrupted one.
TEST(CheckpointRestart, SigtermStopsAtTheNextWindowEndWithACheckpointThatContinuesTheRun) {
  const fs::path dir = fresh_directory("checkpoint_sigterm");
  JobOptions o;
  o.end_time = 2.0;  // 800 windows of at least 5 ms: still running when the signal comes
  o.extrapolation = "linear";
  o.left_args = "[--window-delay, 0.005]";
  const fs::path job = write_job(dir, o);
  const auto [stopped, window] = stop_with_sigterm(dir, job);
  ASSERT_EQ(stopped.exit_code, 5) << stopped.output;
  EXPECT_THAT(stopped.output, HasSubstr("stopped at the checkpoint of window"));
  ASSERT_GT(window, 0u);
  for (const char* participant : {"left", "right"}) {
    const auto summary =
        nlohmann::json::parse(read_text(dir / "stopped" / participant / "summary.json"));
    EXPECT_EQ(summary["status"]["exit_code"].get<int>(), 0) << participant;
  }
  const auto summary = nlohmann::json::parse(read_text(dir / "stopped" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"].get<int>(), 5);

  const auto whole = run_job(job, dir / "whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const auto continued = run_job(job, dir / "continued",
                                 {"--restart", checkpoint_of(dir / "stopped", window).string()});
  ASSERT_EQ(continued.exit_code, 0) << continued.output;
  const std::size_t rows = expect_same_continuation(dir / "whole", dir / "continued", window,
                                                    2.5e-3 * static_cast<double>(window));
  std::printf(
      "SIGTERM: stopped after window %zu of 800; %zu rows after it equal the "
      "uninterrupted run's\n",
      window, rows);
  EXPECT_LT(window, 800u);
}

class RefusedCheckpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_directory(std::string("checkpoint_refused_") +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    job_ = write_job(dir_, JobOptions{});
    const auto r = run_job(job_, dir_ / "run", {"--checkpoint-every", "10"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    checkpoint_ = checkpoint_of(dir_ / "run", 10);
  }
  ProcessResult restart(const fs::path& job) {
    return run_job(job, dir_ / "continued", {"--restart", checkpoint_.string()});
  }
  fs::path dir_, job_, checkpoint_;
};

TEST_F(RefusedCheckpoint, ACheckpointOfAnotherJobIsRefused) {
  JobOptions other;
  other.end_time = 0.06;
  const fs::path other_dir = dir_ / "other";
  fs::create_directories(other_dir);
  const auto r = restart(write_job(other_dir, other));
  EXPECT_EQ(r.exit_code, exit_bad_input) << r.output;
  EXPECT_THAT(r.output, HasSubstr("it belongs to job 'e2e' with config hash"));
  EXPECT_FALSE(fs::exists(dir_ / "continued" / "left")) << "a participant was started";
}

TEST_F(RefusedCheckpoint, ATruncatedFileIsRefused) {
  const fs::path state = checkpoint_ / "left" / "state.h5";
  fs::resize_file(state, fs::file_size(state) / 2);
  const auto r = restart(job_);
  EXPECT_EQ(r.exit_code, exit_bad_input) << r.output;
  EXPECT_THAT(r.output, HasSubstr("left/state.h5 has"));
  EXPECT_THAT(r.output, HasSubstr("(truncated?)"));
}

TEST_F(RefusedCheckpoint, AMissingFileOrManifestIsRefused) {
  fs::remove(checkpoint_ / "coupler.h5");
  auto r = restart(job_);
  EXPECT_EQ(r.exit_code, exit_bad_input) << r.output;
  EXPECT_THAT(r.output, HasSubstr("coupler.h5 is missing"));
  fs::remove(checkpoint_ / "manifest.json");
  r = restart(job_);
  EXPECT_EQ(r.exit_code, exit_bad_input) << r.output;
  EXPECT_THAT(r.output, HasSubstr("it has no manifest.json"));
}

TEST_F(RefusedCheckpoint, AChangedFileIsRefused) {
  const fs::path state = checkpoint_ / "right" / "participant.h5";
  std::string bytes = read_text(state);
  bytes[bytes.size() - 1] = static_cast<char>(bytes[bytes.size() - 1] ^ 0x5a);
  std::ofstream(state, std::ios::binary | std::ios::trunc) << bytes;
  const auto r = restart(job_);
  EXPECT_EQ(r.exit_code, exit_bad_input) << r.output;
  EXPECT_THAT(r.output, HasSubstr("right/participant.h5 has changed since it was written"));
}

TEST(CheckpointRestart, BadOptionsAndParticipantsThatCannotTakePartAreRefused) {
  const fs::path dir = fresh_directory("checkpoint_bad_options");
  for (const std::string every : {"0", "abc", "-3s", "1.5"}) {
    const auto r = run_job(write_job(dir, JobOptions{}), dir / ("run_" + every),
                           {"--checkpoint-every", every});
    EXPECT_EQ(r.exit_code, exit_bad_input) << every << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("--checkpoint-every '" + every + "'"));
  }
  JobOptions o;
  o.right_args = "[--not-checkpointable]";
  const auto r =
      run_job(write_job(dir, o), dir / "run_not_checkpointable", {"--checkpoint-every", "5"});
  EXPECT_EQ(r.exit_code, exit_bad_input) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participant 'right' (cosim participant"));
  EXPECT_THAT(r.output, HasSubstr("cannot write its state into a checkpoint"));
  const fs::path serial = fresh_directory("checkpoint_serial");
  write_fixed_point_case(serial, "coupling: {scheme: serial-explicit, first: left}\n");
  const auto s = run_job(serial / "job.yaml", serial / "run", {"--checkpoint-every", "2"});
  EXPECT_EQ(s.exit_code, exit_bad_input) << s.output;
  EXPECT_THAT(s.output, HasSubstr("couples serially"));
}

}  // namespace
}  // namespace cosim::testing
