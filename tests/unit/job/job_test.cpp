// Job files are checked in full before anything starts: every mistake is an
// InputError (exit code 2) naming the file, line, column and key path.

#include "job/job.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cosim/error.hpp"
#include "replaced_text.hpp"
#include "scratch_directory.hpp"

namespace cosim::job {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

constexpr const char* valid_job = R"(kind: job
name: demo
end_time: 1.0
window: 0.01
participants:
  soil:
    executable: mpm_solver
    meshes: {mpm_grid: {kind: uniform_grid, dim: 2}}
    writes: {solid_fraction: mpm_grid}
    reads: {pore_pressure: mpm_grid}
  water:
    executable: ice_fluid
    meshes: {ice_grid: {kind: uniform_grid, dim: 2}}
    writes: {pore_pressure: ice_grid}
    reads: {solid_fraction: ice_grid}
exchange:
  - {field: solid_fraction, from: soil, to: water, mapping: {constraint: conservative, bounds: [0, 0.64]}}
  - {field: pore_pressure, from: water, to: soil, mapping: consistent}
)";

class JobFile : public ::testing::Test {
 protected:
  fs::path write(const std::string& text) const { return scratch_.write("job.yaml", text); }
  // Replaces the first occurrence of `from` in the valid job by `to`.
  std::string variant(const std::string& from, const std::string& to) {
    return cosim::testing::replaced(valid_job, from, to);
  }
  std::string error_of(const std::string& text) {
    try {
      load_job(write(text));
    } catch (const InputError& e) {
      EXPECT_EQ(e.code(), ExitCode::bad_input);
      return e.what();
    }
    ADD_FAILURE() << "accepted:\n" << text;
    return {};
  }

  cosim::testing::ScratchDirectory scratch_;
};

TEST_F(JobFile, ValidJobLoads) {
  const Job job = load_job(write(valid_job));
  EXPECT_EQ(job.name, "demo");
  EXPECT_EQ(job.windows(), 100u);
  ASSERT_EQ(job.exchanges.size(), 2u);
  ASSERT_TRUE(job.exchanges[0].mapping.bounds);
  EXPECT_EQ(job.exchanges[0].mapping.bounds->second, 0.64);
  EXPECT_EQ(job.config_hash.size(), 16u);
  EXPECT_EQ(job.transport, TransportKind::zmq);
}

TEST_F(JobFile, UnknownKeyIsLocatedWithASuggestion) {
  const std::string e = error_of(variant("end_time: 1.0", "end_tme: 1.0"));
  EXPECT_THAT(e, HasSubstr("job.yaml:3:1"));
  EXPECT_THAT(e, HasSubstr("end_time"));
}

TEST_F(JobFile, NegativeWindowIsRefusedAtItsLine) {
  const std::string e = error_of(variant("window: 0.01", "window: -0.01"));
  EXPECT_THAT(e, HasSubstr("job.yaml:4:"));
  EXPECT_THAT(e, HasSubstr("window"));
}

TEST_F(JobFile, EndTimeBeforeStartIsRefused) {
  const std::string e = error_of(variant("end_time: 1.0", "start_time: 2.0\nend_time: 1.0"));
  EXPECT_THAT(e, HasSubstr("end_time"));
  EXPECT_THAT(e, HasSubstr("not after the start time"));
}

TEST_F(JobFile, FieldReadThatNobodyWritesIsRefused) {
  const std::string e = error_of(variant("reads: {pore_pressure: mpm_grid}",
                                         "reads: {pore_pressure: mpm_grid, drag: mpm_grid}"));
  EXPECT_THAT(e, HasSubstr("participants.soil.reads.drag"));
  EXPECT_THAT(e, HasSubstr("no exchange entry sends it"));
}

TEST_F(JobFile, MeshDimensionMismatchIsRefused) {
  const std::string e = error_of(
      variant("ice_grid: {kind: uniform_grid, dim: 2}", "ice_grid: {kind: uniform_grid, dim: 3}"));
  EXPECT_THAT(e, HasSubstr("exchange[0]"));
  EXPECT_THAT(e, HasSubstr("from 2D mesh 'soil.mpm_grid' to 3D mesh 'water.ice_grid'"));
}

TEST_F(JobFile, UnknownParticipantAndWrongTypesAreRefused) {
  EXPECT_THAT(error_of(variant("from: water", "from: air")),
              HasSubstr("no participant named 'air'"));
  EXPECT_THAT(error_of(variant("end_time: 1.0", "end_time: soon")), HasSubstr("end_time"));
  EXPECT_THAT(error_of(variant("name: demo", "name: demo\ntransport: pigeon")),
              HasSubstr("transport"));
  EXPECT_THAT(error_of(variant("kind: job", "kind: mpm_case")), HasSubstr("job"));
}

TEST_F(JobFile, ConsistentMappingCannotHaveBounds) {
  EXPECT_THAT(error_of(variant("constraint: conservative", "constraint: consistent")),
              HasSubstr("bounds apply to conservative transfers"));
}

// `ranks` of a participant: its MPI ranks in the MPMD launch. Lines 7 and 12
// of the valid job are soil's and water's `executable`: a `ranks` key put
// after one is on line 8 or 13.
TEST_F(JobFile, RanksDefaultsToOneAndIsRead) {
  const Job one = load_job(write(valid_job));
  ASSERT_EQ(one.participants.size(), 2u);
  EXPECT_EQ(one.participants[0].ranks, 1);
  EXPECT_EQ(one.participants[1].ranks, 1);

  std::string text =
      cosim::testing::replaced(valid_job, "window: 0.01", "window: 0.01\ntransport: mpi");
  text = cosim::testing::replaced(text, "executable: mpm_solver",
                                  "executable: mpm_solver\n    ranks: 4");
  const Job four = load_job(write(text));
  EXPECT_EQ(four.transport, TransportKind::mpi);
  EXPECT_EQ(four.participant("soil")->ranks, 4);
  EXPECT_EQ(four.participant("soil")->ranks_where.line, 9);
  EXPECT_EQ(four.participant("water")->ranks, 1);
}

// The hash without ranks leaves out the participants' rank counts alone:
// a checkpoint restarts on other counts of ranks, not with another job.
TEST_F(JobFile, TheHashWithoutRanksLeavesOutTheRankCountsAlone) {
  std::string text =
      cosim::testing::replaced(valid_job, "window: 0.01", "window: 0.01\ntransport: mpi");
  const auto with_ranks = [&](const std::string& soil, const std::string& water) {
    std::string t = cosim::testing::replaced(text, "executable: mpm_solver",
                                             "executable: mpm_solver\n    ranks: " + soil);
    return load_job(write(cosim::testing::replaced(t, "executable: ice_fluid",
                                                   "executable: ice_fluid\n    ranks: " + water)));
  };
  const Job two = with_ranks("2", "1");
  const Job three = with_ranks("3", "12");
  EXPECT_NE(two.config_hash, three.config_hash);
  EXPECT_EQ(two.config_hash_without_ranks, three.config_hash_without_ranks);
  EXPECT_NE(two.config_hash, two.config_hash_without_ranks);
  const Job longer = load_job(write(
      cosim::testing::replaced(cosim::testing::replaced(text, "executable: mpm_solver",
                                                        "executable: mpm_solver\n    ranks: 2"),
                               "end_time: 1.0", "end_time: 2.0")));
  EXPECT_NE(longer.config_hash_without_ranks, two.config_hash_without_ranks);
}

TEST_F(JobFile, RanksBelowOneIsRefusedAtItsKeyAndLine) {
  for (const char* value : {"0", "-3"}) {
    const std::string e = error_of(variant(
        "executable: mpm_solver", std::string("executable: mpm_solver\n    ranks: ") + value));
    EXPECT_THAT(e, HasSubstr("job.yaml:8:")) << e;
    EXPECT_THAT(e, HasSubstr("participants.soil.ranks")) << e;
    EXPECT_THAT(e, HasSubstr("must be in [1, 100000]")) << e;
  }
  const std::string e =
      error_of(variant("executable: mpm_solver", "executable: mpm_solver\n    ranks: 1.5"));
  EXPECT_THAT(e, HasSubstr("job.yaml:8:"));
  EXPECT_THAT(e, HasSubstr("participants.soil.ranks"));
}

TEST_F(JobFile, SeveralRanksNeedTheMpiTransport) {
  const std::string e =
      error_of(variant("executable: ice_fluid", "executable: ice_fluid\n    ranks: 2"));
  EXPECT_THAT(e, HasSubstr("job.yaml:13:")) << e;
  EXPECT_THAT(e, HasSubstr("participants.water.ranks")) << e;
  EXPECT_THAT(e, HasSubstr("needs 'transport: mpi'")) << e;
}

// A program that starts its solver's processes itself (openfoam_adapter's
// OpenFOAM, `ranks: solver_processes` in its backend descriptor) takes the
// job's `ranks` as their count: it is launched as one process, on either
// transport, and its `ranks` stays 1.
TEST_F(JobFile, RanksOfAProgramStartingItsProcessesAreItsSolverProcesses) {
  const std::string text = variant("executable: ice_fluid", "executable: ice_fluid\n    ranks: 3");
  const Job job = load_job(write(text), {"ice_fluid"});
  EXPECT_EQ(job.transport, TransportKind::zmq);
  EXPECT_EQ(job.participant("water")->ranks, 1);
  EXPECT_EQ(job.participant("water")->solver_processes, 3);
  EXPECT_EQ(job.participant("soil")->solver_processes, 0);
  // By the executable's file name, wherever it lies.
  const Job by_path = load_job(
      write(variant("executable: ice_fluid", "executable: /opt/bin/ice_fluid\n    ranks: 2")),
      {"ice_fluid"});
  EXPECT_EQ(by_path.participant("water")->solver_processes, 2);
  // One rank: the program's own setting holds.
  EXPECT_EQ(load_job(write(valid_job), {"ice_fluid"}).participant("water")->solver_processes, 0);
  // Other programs' ranks stay MPI ranks.
  EXPECT_THAT(error_of(text), HasSubstr("needs 'transport: mpi'"));
}

TEST_F(JobFile, YamlSyntaxErrorsAreLocated) {
  EXPECT_THAT(error_of("kind: job\nname: [unclosed\n"), HasSubstr("job.yaml:"));
}

}  // namespace
}  // namespace cosim::job
