// swe_fluid standalone under `mpirun -np N` (label mpi): the radial dam
// break over a bump with gauges, on 1 process and on 2, 3 and 4 ranks, must
// write the same files bit for bit (water.csv, gauges.csv, every snapshot's
// datasets and attributes, the XDMF index, the summary's conserved
// figures); cases a decomposed run cannot take, and an output directory
// already in use, are refused with exit 2 by every rank, nothing lost.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "hdf5_contents.hpp"
#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

constexpr const char* dam_break_case = R"(kind: swe_case
name: radial_dam_break_over_a_bump
dimension: 2
mesh: {origin: [-2.0, -1.5], upper: [2.0, 1.5], cells: [61, 45]}
physics: {manning: 0.02}
bed:
  base: 0.0
  bumps:
    - {centre: [0.8, 0.3], radius: 0.5, height: 0.7}
initial:
  free_surface: 0.5
  regions:
    - {circle: {centre: [-0.5, 0.0], radius: 0.6}, free_surface: 1.0}
boundaries: {x_min: wall, x_max: transmissive, y_min: wall, y_max: wall}
time: {end_time: 0.3}
output:
  every: 0.1
  gauges:
    - {name: east, position: [1.2, 0.0]}
    - {name: north, position: [-0.5, 1.2]}
)";

ProcessResult run_swe(const fs::path& config, const fs::path& output, int ranks) {
  std::vector<std::string> args;
  if (ranks > 0) args = {MPIEXEC, "--oversubscribe", "-np", std::to_string(ranks)};
  for (const std::string& a : {binary("swe_fluid").string(), std::string("--config"),
                               config.string(), std::string("--output"), output.string()})
    args.push_back(a);
  return run(args, std::chrono::seconds(120));
}

fs::path write_case(const fs::path& dir, const std::string& text) {
  fs::create_directories(dir);
  const fs::path file = dir / "case.yaml";
  write_text(file, text);
  return file;
}

TEST(SweFluidRanks, TheFilesOfEveryRankCountAreTheSameBitForBit) {
  const fs::path dir = fresh_directory("swe_fluid_ranks");
  const fs::path config = write_case(dir, dam_break_case);
  const ProcessResult whole = run_swe(config, dir / "one_process", 0);
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const std::vector<std::string> snapshots{"swe_000000.h5", "swe_000001.h5", "swe_000002.h5",
                                           "swe_000003.h5"};
  for (int ranks : {2, 3, 4}) {
    const fs::path out = dir / ("ranks_" + std::to_string(ranks));
    const ProcessResult split = run_swe(config, out, ranks);
    ASSERT_EQ(split.exit_code, 0) << split.output;
    for (const char* file : {"water.csv", "gauges.csv", "swe.xdmf"})
      EXPECT_EQ(read_text(out / file), read_text(dir / "one_process" / file))
          << file << " on " << ranks << " ranks";
    for (const std::string& snapshot : snapshots)
      EXPECT_EQ(hdf5_contents(out / snapshot), hdf5_contents(dir / "one_process" / snapshot))
          << snapshot << " on " << ranks << " ranks";
    const std::string summary = read_text(out / "summary.json");
    const std::string reference = read_text(dir / "one_process" / "summary.json");
    const auto conserved = [](const std::string& s) {
      const auto from = s.find("\"conserved\"");
      return s.substr(from, s.find("\"finished_at\"") - from);
    };
    EXPECT_EQ(conserved(summary), conserved(reference)) << ranks << " ranks";
    EXPECT_NE(summary.find("\"ranks\": " + std::to_string(ranks)), std::string::npos);
    for (int r = 1; r < ranks; ++r)
      EXPECT_TRUE(fs::exists(out / "ranks" / ("rank_" + std::to_string(r)) / "log.txt"));
  }
}

void expect_refused(const std::string& case_text, const std::string& key, int ranks) {
  const fs::path dir = fresh_directory("swe_fluid_ranks_refused");
  const fs::path config = write_case(dir, case_text);
  const ProcessResult result = run_swe(config, dir / "run", ranks);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  const std::string summary = read_text(dir / "run" / "summary.json");
  EXPECT_NE(summary.find("bad_input"), std::string::npos) << summary;
  EXPECT_NE(summary.find("case.yaml: key '" + key + "'"), std::string::npos) << summary;
  EXPECT_FALSE(fs::exists(dir / "run" / "swe_000000.h5"));
}

TEST(SweFluidRanks, RefusesBlocksNarrowerThanTheGhostLayers) {
  expect_refused(replaced(dam_break_case, "cells: [61, 45]", "cells: [5, 3]"), "mesh.cells", 3);
}

TEST(SweFluidRanks, RefusesALineAndTheTwoPhaseModeOnSeveralRanks) {
  expect_refused(read_text(fs::path(COSIM_SOURCE_DIR) / "configs/swe/dry_dam_break.yaml"),
                 "dimension", 2);
  expect_refused(std::string(dam_break_case) + R"(two_phase:
  solid_layer: {depth: 0.2, density: 2000, velocity: [0.0, 0.0], box: {min: [0.0, 0.0], max: [1.0, 1.0]}}
)",
                 "two_phase", 2);
}

TEST(SweFluidRanks, LeavesAnOutputDirectoryInUseAsItWas) {
  const fs::path dir = fresh_directory("swe_fluid_ranks_in_use");
  const fs::path config = write_case(dir, dam_break_case);
  fs::create_directories(dir / "run");
  write_text(dir / "run" / "earlier.txt", "an earlier run's file\n");
  const ProcessResult result = run_swe(config, dir / "run", 2);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_EQ(read_text(dir / "run" / "earlier.txt"), "an earlier run's file\n");
  EXPECT_FALSE(fs::exists(dir / "run" / "ranks"));
  EXPECT_FALSE(fs::exists(dir / "run" / "summary.json"));
}

}  // namespace
}  // namespace cosim::testing
