// swe_fluid standalone under `mpirun -np N` (label mpi): the radial dam
// break over a bump with gauges, on 1 process and on 2, 3 and 4 ranks, must
// write the same files: bit for bit the snapshots (every dataset and
// attribute, written together by the ranks), the XDMF index, gauges.csv and
// the water's extremes; to round-off the volumes and momenta, which the
// ranks sum in another order; cases a decomposed run cannot take, and an output directory
// already in use, are refused with exit 2 by every rank, nothing lost.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "demo_job.hpp"
#include "hdf5_contents.hpp"
#include "launched_program.hpp"
#include "replaced_text.hpp"
#include "restart_continuation.hpp"
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
  return run_launched("swe_fluid", config, output, ranks);
}

TEST(SweFluidRanks, EveryRankCountWritesTheFilesOfOneProcess) {
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
    for (const char* file : {"gauges.csv", "swe.xdmf"})
      EXPECT_EQ(read_text(out / file), read_text(dir / "one_process" / file))
          << file << " on " << ranks << " ranks";
    for (const std::string& snapshot : snapshots)
      EXPECT_EQ(hdf5_contents(out / snapshot), hdf5_contents(dir / "one_process" / snapshot))
          << snapshot << " on " << ranks << " ranks";
    // The water's extremes are exact; its volume is summed in another order.
    const auto water = read_csv(out / "water.csv");
    const auto reference_water = read_csv(dir / "one_process" / "water.csv");
    ASSERT_EQ(water.size(), reference_water.size());
    for (std::size_t row = 0; row < water.size(); ++row)
      for (std::size_t column = 0; column < water[row].size(); ++column)
        if (column == 1)
          EXPECT_NEAR(water[row][1], reference_water[row][1], 1e-14 * reference_water[row][1]);
        else
          EXPECT_EQ(water[row][column], reference_water[row][column]) << "column " << column;
    const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
    const auto reference = nlohmann::json::parse(read_text(dir / "one_process" / "summary.json"));
    const double volume = reference["conserved"]["water_volume"]["end"].get<double>();
    for (const char* quantity : {"water_volume", "momentum_x", "momentum_y"})
      for (const char* when : {"start", "end"})
        EXPECT_NEAR(summary["conserved"][quantity][when].get<double>(),
                    reference["conserved"][quantity][when].get<double>(), 1e-13 * 1000.0 * volume)
            << quantity << " at the " << when << " on " << ranks << " ranks";
    EXPECT_EQ(summary["case"]["ranks"], ranks);
    EXPECT_EQ(summary["case"]["cells"], reference["case"]["cells"]);
    EXPECT_EQ(summary["steps"], reference["steps"]);
    for (int r = 1; r < ranks; ++r)
      EXPECT_TRUE(fs::exists(out / "ranks" / ("rank_" + std::to_string(r)) / "log.txt"));
  }
}

void expect_refused(const std::string& case_text, const std::string& key, int ranks) {
  expect_refused_on_ranks("swe_fluid", case_text, key, ranks, "swe_000000.h5");
}

// A coupled job over MPI whose water (swe_fluid) runs on 2 ranks, a
// partitioned participant: configs/soil_block_into_basin_3d.yaml (a 3D MPM
// clay block collapsing into a 2D shallow-water basin, the soil's surface
// the water's bed), to 0.1 s, against the same job with the water on one
// process; and with the soil on 2 ranks too (its bed elevation the envelope
// of both ranks' points, the traction shared over both ranks' surface
// points). The decomposed shallow water and MPM are bitwise the whole ones,
// so the water's snapshots and the soil's must be the same bit for bit.
// configs/soil_block_into_basin_3d.yaml to 0.1 s (50 windows) over MPI with
// the soil and the water on the ranks given, written into `run_dir`.
fs::path write_basin_job(const fs::path& run_dir, int soil_ranks, int water_ranks) {
  const fs::path configs = fs::path(COSIM_SOURCE_DIR) / "configs";
  fs::create_directories(run_dir / "mpm");
  fs::create_directories(run_dir / "swe");
  fs::copy_file(configs / "mpm" / "soil_block_3d.yaml", run_dir / "mpm" / "soil_block_3d.yaml");
  fs::copy_file(configs / "swe" / "basin_2d.yaml", run_dir / "swe" / "basin_2d.yaml");
  std::string job = replaced(read_text(configs / "soil_block_into_basin_3d.yaml"), "end_time: 3.0",
                             "end_time: 0.1\ntransport: mpi");
  job = replaced(job, "    config: swe/basin_2d.yaml\n",
                 fmt::format("    config: swe/basin_2d.yaml\n    ranks: {}\n", water_ranks));
  job = replaced(job, "    config: mpm/soil_block_3d.yaml\n",
                 fmt::format("    config: mpm/soil_block_3d.yaml\n    ranks: {}\n", soil_ranks));
  write_text(run_dir / "job.yaml", job);
  return run_dir / "job.yaml";
}

TEST(SweFluidRanks, ACoupledWaterAndSoilOnTwoRanksGiveTheOneProcessRunBitForBit) {
  const fs::path dir = fresh_directory("swe_fluid_coupled_ranks");
  const auto run_dir_of = [&](int soil_ranks, int water_ranks) {
    return dir / fmt::format("soil_{}_water_{}", soil_ranks, water_ranks);
  };
  const std::pair<int, int> layouts[] = {{1, 1}, {1, 2}, {2, 2}};
  for (const auto& [soil_ranks, water_ranks] : layouts) {
    const fs::path run_dir = run_dir_of(soil_ranks, water_ranks);
    const fs::path job = write_basin_job(run_dir, soil_ranks, water_ranks);
    const ProcessResult result = cosim_run(job, run_dir / "run", 240);
    ASSERT_EQ(result.exit_code, 0) << result.output << read_text(run_dir / "run" / "mpirun.log");
  }
  const fs::path one = run_dir_of(1, 1) / "run";
  for (const auto& [soil_ranks, water_ranks] : {layouts[1], layouts[2]}) {
    SCOPED_TRACE(fmt::format("soil on {} ranks, water on {}", soil_ranks, water_ranks));
    const fs::path two = run_dir_of(soil_ranks, water_ranks) / "run";
    int compared = 0;
    for (const auto& [participant, prefix] :
         {std::pair<std::string, std::string>{"water", "swe_"}, {"soil", "particles_"}})
      for (const auto& entry : fs::directory_iterator(one / participant)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) != 0 || entry.path().extension() != ".h5") continue;
        EXPECT_EQ(hdf5_contents(entry.path()), hdf5_contents(two / participant / name))
            << participant << "/" << name;
        ++compared;
      }
    EXPECT_GE(compared, 4);
    EXPECT_EQ(read_text(one / "water" / "gauges.csv"), read_text(two / "water" / "gauges.csv"));
    EXPECT_EQ(nlohmann::json::parse(read_text(two / "water" / "summary.json"))["windows"], 50);
    EXPECT_EQ(nlohmann::json::parse(read_text(two / "soil" / "summary.json"))["case"]["ranks"],
              soil_ranks == 1 ? nlohmann::json() : nlohmann::json(soil_ranks));
  }
}

// The same job with both on 2 ranks and a checkpoint every 25 windows: the
// run continued from one writes what the uninterrupted run wrote after it,
// bit for bit (each water rank its block, each soil rank its points); with
// the soil on 1 rank instead (its points joined from both parts), or the
// water on 1 or 3 (each block's cells and ghosts joined from the blocks that
// own them), the same last snapshots, as the ranks of both give the
// one-process run bit for bit.
TEST(SweFluidRanks, ACoupledJobOnRanksContinuesFromItsCheckpoint) {
  const fs::path dir = fresh_directory("swe_fluid_coupled_ranks_restart");
  const fs::path job = write_basin_job(dir / "two", 2, 2);
  expect_restart_continues(dir / "two", job, "25", 25);
  const fs::path checkpoint = checkpoint_of(dir / "two" / "whole", 25);
  EXPECT_TRUE(fs::exists(checkpoint / "water" / "rank_1" / "state.h5"));
  for (const auto& [soil_ranks, water_ranks] :
       {std::pair{1, 2}, std::pair{2, 1}, std::pair{2, 3}}) {
    SCOPED_TRACE(fmt::format("soil on {} ranks, water on {}", soil_ranks, water_ranks));
    const fs::path run_dir = dir / fmt::format("soil_{}_water_{}", soil_ranks, water_ranks);
    const fs::path job_on = write_basin_job(run_dir, soil_ranks, water_ranks);
    const ProcessResult r =
        cosim_run(job_on, run_dir / "run", 240, {"--restart", checkpoint.string()});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(expect_same_last_snapshots(dir / "two" / "whole", run_dir / "run"), 2u);
  }
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
  expect_directory_in_use_kept("swe_fluid", dam_break_case);
}

}  // namespace
}  // namespace cosim::testing
