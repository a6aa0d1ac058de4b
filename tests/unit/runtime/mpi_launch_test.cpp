// The MPMD mpirun line of an MPI job: each participant on its `ranks`, the
// binding by the machine's cores, and the peer names of the ranks.

#include "runtime/mpi_launch.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "mpmd_job.hpp"

namespace cosim::runtime {
namespace {

using ::testing::ElementsAre;
using Words = std::vector<std::string>;

class MpiLaunch : public cosim::testing::MpmdJob {
 protected:
  Words command(unsigned cores) const {
    return mpi_command(job_, job_file_, scratch_ / "run", "job-42", 30.0, cores);
  }
};

// Where `word` is in `words` from `from` on; words.size() when it is not.
std::size_t index_of(const Words& words, const std::string& word, std::size_t from = 0) {
  return static_cast<std::size_t>(
      std::find(words.begin() + static_cast<long>(from), words.end(), word) - words.begin());
}

TEST_F(MpiLaunch, EachApplicationRunsOnItsRanks) {
  const Words cmd = command(64);
  // The -np of each application, in launch order, and what follows it.
  Words counts, programs;
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i + 2 < cmd.size(); ++i)
    if (cmd[i] == "-np") {
      counts.push_back(cmd[i + 1]);
      programs.push_back(cmd[i + 2]);
      at.push_back(i);
    }
  EXPECT_THAT(counts, ElementsAre("1", "2", "3"));
  ASSERT_EQ(programs.size(), 3u);
  EXPECT_EQ(std::filesystem::path(programs[0]).filename(), "cosim");
  EXPECT_EQ(std::filesystem::path(programs[1]).lexically_normal(), program("soil_solver"));
  EXPECT_EQ(std::filesystem::path(programs[2]).lexically_normal(), program("water_solver"));
  // Applications are separated by ':' and each names itself.
  EXPECT_EQ(cmd[at[1] - 1], ":");
  EXPECT_EQ(cmd[at[2] - 1], ":");
  EXPECT_EQ(cmd[index_of(cmd, "--cosim-name", at[1]) + 1], "soil");
  EXPECT_LT(index_of(cmd, "--cosim-name", at[1]), at[2]);
  EXPECT_EQ(cmd[index_of(cmd, "--cosim-name", at[2]) + 1], "water");
  EXPECT_EQ(cmd[index_of(cmd, "--cosim-endpoint", at[2]) + 1], "mpi://");
  // soil's own arguments end its application.
  EXPECT_EQ(cmd[at[2] - 3], "--threads");
  EXPECT_EQ(cmd[at[2] - 2], "1");
  EXPECT_EQ(cmd[index_of(cmd, "--job-id") + 1], "job-42");
}

TEST_F(MpiLaunch, RanksThatFitTheCoresAreBoundOthersAreNot) {
  ASSERT_EQ(mpi_world_size(job_), 6);  // 1 + 2 + 3
  EXPECT_THAT(binding_options(6, 6), ElementsAre("--bind-to", "core"));
  EXPECT_THAT(binding_options(6, 5), ElementsAre("--bind-to", "none"));
  EXPECT_THAT(binding_options(6, 0), ElementsAre("--bind-to", "none"));  // unknown

  for (const auto& [cores, binding] : {std::pair{64u, "core"}, std::pair{2u, "none"}}) {
    const Words cmd = command(cores);
    const std::size_t bind = index_of(cmd, "--bind-to");
    ASSERT_LT(bind + 1, cmd.size()) << cores;
    EXPECT_EQ(cmd[bind + 1], binding) << cores;
    EXPECT_EQ(index_of(cmd, "--bind-to", bind + 1), cmd.size()) << "bound twice";
    // Before the first application, with the options that were there before.
    EXPECT_LT(bind, index_of(cmd, "-np"));
    EXPECT_EQ(cmd[0], "mpirun");
    EXPECT_LT(index_of(cmd, "--oversubscribe"), index_of(cmd, "-np"));
    const std::size_t mca = index_of(cmd, "--mca");
    ASSERT_LT(mca + 2, cmd.size());
    EXPECT_EQ(cmd[mca + 1], "mpi_yield_when_idle");
  }
}

// 1 + 2 + 3 ranks fit one core (16 at most); 1 + 40 + 3 do not fit two, and
// the refusal names the participant with the most ranks at its key.
TEST_F(MpiLaunch, MoreRanksThanTheCoresCanRunAreRefused) {
  EXPECT_NO_THROW(check_ranks_fit(job_, 1));
  EXPECT_NO_THROW(check_ranks_fit(job_, 0));  // unknown: mpirun decides
  std::string text = job_text();
  text.replace(text.find("ranks: 2"), 8, "ranks: 40");
  const job::Job wide = job::load_job(scratch_.write("wide.yaml", text));
  EXPECT_NO_THROW(check_ranks_fit(wide, 3));  // 44 <= 48
  try {
    check_ranks_fit(wide, 2);
    FAIL() << "44 ranks on 2 cores were not refused";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("wide.yaml:7:"), std::string::npos) << what;
    EXPECT_NE(what.find("participants.soil.ranks"), std::string::npos) << what;
    EXPECT_NE(what.find("44 ranks"), std::string::npos) << what;
    EXPECT_NE(what.find("--slurm-script"), std::string::npos) << what;
  }
}

TEST_F(MpiLaunch, ThisMachinesCoreCountIsKnown) {
  EXPECT_GE(available_cores(), 1u);
  // The line without a core count uses it.
  const Words expected = command(available_cores());
  EXPECT_EQ(mpi_command(job_, job_file_, scratch_ / "run", "job-42", 30.0), expected);
}

// A participant whose program starts its solver's processes itself runs
// as one rank of the MPMD line, told their count; they share the cores, so
// they count in the binding.
TEST_F(MpiLaunch, AProgramStartingItsSolverProcessesIsOneRankToldTheirCount) {
  const job::Job job = job::load_job(job_file_, {"water_solver"});
  ASSERT_EQ(job.participant("water")->solver_processes, 3);
  EXPECT_EQ(mpi_world_size(job), 4);  // 1 + 2 + 1
  const Words cmd = mpi_command(job, job_file_, scratch_ / "run", "job-42", 30.0, 6);
  const std::size_t water =
      index_of(cmd, "-np", index_of(cmd, "-np", index_of(cmd, "-np") + 1) + 1);
  ASSERT_LT(water + 1, cmd.size());
  EXPECT_EQ(cmd[water + 1], "1");
  const std::size_t processes = index_of(cmd, "--cosim-solver-processes");
  ASSERT_LT(processes + 1, cmd.size());
  EXPECT_GT(processes, water);
  EXPECT_EQ(cmd[processes + 1], "3");
  EXPECT_EQ(index_of(cmd, "--cosim-solver-processes", processes + 1), cmd.size());
  // 4 ranks and 3 OpenFOAM-like processes do not fit 6 cores.
  EXPECT_EQ(cmd[index_of(cmd, "--bind-to") + 1], "none");
  const Words seven = mpi_command(job, job_file_, scratch_ / "run", "job-42", 30.0, 7);
  EXPECT_EQ(seven[index_of(seven, "--bind-to") + 1], "core");
}

TEST_F(MpiLaunch, EveryRankAfterTheCouplersHasAPeerName) {
  EXPECT_EQ(part_peer_name("soil", 0, 1), "soil");
  EXPECT_EQ(part_peer_name("soil", 0, 2), "soil[0]");
  EXPECT_EQ(part_peer_name("soil", 1, 2), "soil[1]");
  EXPECT_THAT(rank_peer_names(job_),
              ElementsAre("soil[0]", "soil[1]", "water[0]", "water[1]", "water[2]"));
}

}  // namespace
}  // namespace cosim::runtime
