// Participants on several ranks in a coupled job (label mpi): the demo job
// of two test participants over the MPI transport, each participant on 1, 2
// or 3 ranks that hold contiguous parts of its grid. The coupler assembles
// the parts and splits what it sends (m2n::PartitionedHub), so every rank
// count must give the one-rank run's exchange bit for bit, also when ranks
// hold ghosts (elements they read but do not own): the snapshots of
// the exchanged fields, and the heat each window's writer integrated and the
// reader applied (summed over the ranks, to round-off). Checkpoints of the
// job continue on its ranks. A program that does not run on ranks, and a
// rank that dies, end the job with a clear error and no process left.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "demo_job.hpp"
#include "hdf5_contents.hpp"
#include "restart_continuation.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr double end_time = 0.025;  // 10 windows

JobOptions job_on(int left_ranks, int right_ranks) {
  JobOptions o;
  o.transport = "mpi";
  o.end_time = end_time;
  o.output_every = 0.005;
  o.left_ranks = left_ranks;
  o.right_ranks = right_ranks;
  o.name = fmt::format("parts_{}_{}", left_ranks, right_ranks);
  return o;
}

// Column `column` of a participant's CSV log, summed over its ranks' files
// row by row.
std::vector<double> summed_over_ranks(const fs::path& participant_dir, const std::string& file,
                                      int ranks, std::size_t column) {
  std::vector<double> sum;
  for (int r = 0; r < ranks; ++r) {
    const fs::path dir =
        r == 0 ? participant_dir : participant_dir / "ranks" / fmt::format("rank_{}", r);
    const auto rows = read_csv(dir / file);
    sum.resize(rows.size(), 0.0);
    for (std::size_t i = 0; i < rows.size(); ++i) sum[i] += rows[i][column];
  }
  return sum;
}

std::vector<fs::path> snapshots_in(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".h5") files.push_back(entry.path().filename());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(PartitionedParticipants, EveryRankCountExchangesWhatOneRankDoes) {
  const fs::path dir = fresh_directory("partitioned_participants");
  const fs::path one_dir = dir / "one";
  fs::create_directories(one_dir);
  const auto one = cosim_run(write_job(one_dir, job_on(1, 1)), one_dir / "run", 300);
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const auto reference_snapshots = snapshots_in(one_dir / "run" / "exchanged");
  ASSERT_GE(reference_snapshots.size(), 5u);
  const auto heat_sent = read_csv(one_dir / "run" / "left" / "heat_sent.csv");
  ASSERT_EQ(heat_sent.size(), 10u);

  // Ranks that also hold (read, never send) 7 elements of each neighbour's.
  for (const auto& [left, right, ghosts] :
       {std::tuple{2, 2, 0}, std::tuple{3, 1, 0}, std::tuple{1, 3, 0}, std::tuple{2, 3, 7}}) {
    SCOPED_TRACE(fmt::format("left on {} ranks, right on {}, {} ghosts", left, right, ghosts));
    const fs::path case_dir = dir / fmt::format("ranks_{}_{}_{}", left, right, ghosts);
    fs::create_directories(case_dir);
    JobOptions options = job_on(left, right);
    options.left_args = options.right_args = fmt::format("[--ghosts, '{}']", ghosts);
    const auto job = write_job(case_dir, options);
    const auto printed = run({binary("cosim").string(), "run", job.string(), "--output",
                              (case_dir / "run").string(), "--print-mpi-command"},
                             std::chrono::seconds(30));
    ASSERT_EQ(printed.exit_code, 0) << printed.output;
    EXPECT_THAT(printed.output, HasSubstr(fmt::format("-np {} ", left)));
    EXPECT_THAT(printed.output, HasSubstr(fmt::format("-np {} ", right)));

    const auto r = cosim_run(job, case_dir / "run", 300);
    ASSERT_EQ(r.exit_code, 0) << r.output << read_text(case_dir / "run" / "mpirun.log");
    // The coupler's snapshots of what it sent: the same bits.
    const auto snapshots = snapshots_in(case_dir / "run" / "exchanged");
    ASSERT_EQ(snapshots, reference_snapshots);
    for (const auto& file : snapshots)
      EXPECT_EQ(hdf5_contents(case_dir / "run" / "exchanged" / file),
                hdf5_contents(one_dir / "run" / "exchanged" / file))
          << file;
    // The heat integrated by the writer's ranks together, and applied by the
    // reader's ranks together in the next window: conserved, and as on one rank.
    const auto sent = summed_over_ranks(case_dir / "run" / "left", "heat_sent.csv", left, 2);
    const auto applied =
        summed_over_ranks(case_dir / "run" / "right", "heat_applied.csv", right, 2);
    ASSERT_EQ(sent.size(), heat_sent.size());
    ASSERT_EQ(applied.size(), heat_sent.size());
    double worst_sent = 0.0, worst_conserved = 0.0;
    for (std::size_t k = 0; k + 1 < sent.size(); ++k) {
      worst_sent =
          std::max(worst_sent, std::abs(sent[k] - heat_sent[k][2]) / std::abs(heat_sent[k][2]));
      worst_conserved =
          std::max(worst_conserved, std::abs(applied[k + 1] - sent[k]) / std::abs(sent[k]));
    }
    std::printf("left %d ranks, right %d: heat sent vs one rank %.2e, applied vs sent %.2e\n", left,
                right, worst_sent, worst_conserved);
    EXPECT_LE(worst_sent, 1e-12);
    EXPECT_LE(worst_conserved, 1e-12);
    const auto summary = nlohmann::json::parse(read_text(case_dir / "run" / "summary.json"));
    EXPECT_EQ(summary["windows"], 10);
    EXPECT_LE(summary["metrics"]["max_conservative_mapping_error"]["value"].get<double>(), 1e-12);
  }
}

TEST(PartitionedParticipants, AProgramThatDoesNotRunOnRanksIsRefusedWithExit2) {
  const fs::path dir = fresh_directory("partitioned_whole_mesh");
  JobOptions o = job_on(2, 1);
  o.left_args = "[--whole-mesh]";
  const auto r = cosim_run(write_job(dir, o), dir / "run", 120);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  const std::string all = r.output + read_text(dir / "run" / "summary.json") +
                          read_text(dir / "run" / "left" / "summary.json");
  EXPECT_THAT(all, HasSubstr("does not run on several ranks"));
  EXPECT_THAT(all, HasSubstr("participants.left.ranks"));
}

// A checkpoint of an MPI job: every rank of a participant writes its part
// (`rank_<r>/`: this library's state and the solver's), and the run
// continued from it on the same ranks writes what the uninterrupted run
// wrote after it, bit for bit. The test participant restarts only on as
// many ranks as wrote the checkpoint: on others it is refused at once with
// exit 2, naming both counts.
TEST(PartitionedParticipants, AJobOnRanksContinuesFromItsCheckpoint) {
  const fs::path dir = fresh_directory("partitioned_checkpoints");
  JobOptions options = job_on(2, 3);
  options.right_args = "[--ghosts, '7']";
  const fs::path job = write_job(dir, options);
  expect_restart_continues(dir, job, "4", 4);
  const fs::path checkpoint = checkpoint_of(dir / "whole", 4);
  for (const char* part : {"left/rank_0", "left/rank_1", "right/rank_2"}) {
    EXPECT_TRUE(fs::exists(checkpoint / part / "participant.h5")) << part;
    EXPECT_TRUE(fs::exists(checkpoint / part / "state.h5")) << part;
  }
  const auto manifest = nlohmann::json::parse(read_text(checkpoint / "manifest.json"));
  EXPECT_EQ(manifest["ranks"]["left"], 2);
  EXPECT_EQ(manifest["ranks"]["right"], 3);

  JobOptions fewer = options;
  fewer.left_ranks = 1;
  fs::create_directories(dir / "fewer");
  const auto r = cosim_run(write_job(dir / "fewer", fewer), dir / "fewer" / "run", 120,
                           {"--restart", checkpoint.string()});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participant 'left' wrote this checkpoint on 2 ranks; it runs "
                                  "on 1 now"));
}

// SIGTERM to `cosim run` of an MPI job with --checkpoint-every (a batch
// system's wall-time limit): the launcher passes it to the coupler rank,
// which writes a checkpoint at the next window end, every rank of each
// participant its part, and the job ends with exit 5, the participants
// completed; the run continued from it on other ranks writes what the
// uninterrupted run wrote after it.
TEST(PartitionedParticipants, SigtermStopsAnMpiJobAtACheckpoint) {
  const fs::path dir = fresh_directory("partitioned_sigterm");
  JobOptions o = job_on(2, 2);
  o.end_time = 2.0;  // 800 windows of at least 5 ms: still running when the signal comes
  o.left_args = "[--window-delay, 0.005]";
  const fs::path job = write_job(dir, o);
  const auto [stopped, window] = stop_with_sigterm(dir, job);
  ASSERT_EQ(stopped.exit_code, 5) << stopped.output;
  EXPECT_THAT(stopped.output, HasSubstr("stopped at the checkpoint of window"));
  ASSERT_GT(window, 0u);
  EXPECT_LT(window, 800u);
  for (const char* participant : {"left", "right"}) {
    const auto summary =
        nlohmann::json::parse(read_text(dir / "stopped" / participant / "summary.json"));
    EXPECT_EQ(summary["status"]["exit_code"].get<int>(), 0) << participant;
    EXPECT_TRUE(fs::exists(checkpoint_of(dir / "stopped", window) / participant / "rank_1" /
                           "participant.h5"))
        << participant;
  }
  const auto continued = cosim_run(job, dir / "continued", 300,
                                   {"--restart", checkpoint_of(dir / "stopped", window).string()});
  ASSERT_EQ(continued.exit_code, 0) << continued.output;
  const auto summary = nlohmann::json::parse(read_text(dir / "continued" / "summary.json"));
  EXPECT_EQ(summary["restart"]["window"].get<std::size_t>(), window);
  EXPECT_EQ(summary["windows"], 800);
}

TEST(PartitionedParticipants, ARankThatDiesEndsTheJobWithExit3AndNoProcessLeft) {
  const fs::path dir = fresh_directory("partitioned_rank_dies");
  JobOptions o = job_on(2, 2);
  o.end_time = 1000.0;
  o.right_args = "[--raise, SIGKILL, --raise-at, 'window:3', --fault-rank, '1']";
  const auto r = cosim_run(write_job(dir, o), dir / "run", 120);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_THAT(r.output, HasSubstr("participant 'right[1]'"));
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 3);
  for (const fs::path& pid_file :
       {dir / "run" / "left" / "pid", dir / "run" / "left" / "ranks" / "rank_1" / "pid",
        dir / "run" / "right" / "pid"}) {
    ASSERT_TRUE(fs::exists(pid_file)) << pid_file;
    // Ended by mpirun, or by the kernel when mpirun is gone (their parent-death
    // signal): a moment after the job ends.
    const pid_t pid = std::stoi(read_text(pid_file));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (process_exists(pid) && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_FALSE(process_exists(pid)) << pid_file << " outlived the job";
  }
}

}  // namespace
}  // namespace cosim::testing
