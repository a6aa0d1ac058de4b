// mpm_solver standalone under `mpirun -np N` (label mpi): a sand column
// collapsing (GIMP, MUSL, Mohr-Coulomb), on 1 process and on 2, 3 and 4
// ranks whose cuts move to balance the points, must write the same particle
// and grid snapshots bit for bit (every dataset and attribute, written
// together by the ranks, each its owned planes of grid values at the cuts
// of the moment), the same XDMF indices and probes.csv (each probe's point sampled
// by the rank holding it), the same steps, and the totals of one process to round-off (the ranks
// sum them in another order); more ranks than slabs of cell rows, and an output directory already
// in use, are refused with exit 2, nothing lost. Windows that run again
// (--cosim-repeat-windows) keep the files of one process bit for bit.
// Coupled over MPI, a soil on 2 ranks (a partitioned participant) gives the
// one-process run's results, continues from its checkpoints on any count of
// ranks, and a soil that cannot start on its ranks ends the job at once with
// exit 2.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "demo_job.hpp"
#include "hdf5_contents.hpp"
#include "hdf5_reader.hpp"
#include "launched_program.hpp"
#include "replaced_text.hpp"
#include "restart_continuation.hpp"
#include "run_process.hpp"
#include "snapshot_difference.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr const char* column_case = R"(kind: mpm_case
name: sand_column_on_ranks
dimension: 2
grid: {origin: [0, 0], upper: [0.5, 0.25], cells: [50, 25]}
shape: gimp
scheme: musl
time: {end_time: 0.06, safety_factor: 0.4}
gravity: [0, -9.81]
materials:
  sand:
    type: mohr_coulomb
    density: 1800
    youngs_modulus: 2.0e6
    poisson_ratio: 0.3
    friction_angle: 30
    dilation_angle: 0
    cohesion: 0
bodies:
  - name: column
    material: sand
    geometry: {box: {min: [0, 0], max: [0.1, 0.2]}}
    particles_per_cell: 2
    initial_velocity: [0.5, -0.3]
    geostatic: {}
boundaries: {x_min: slip, x_max: slip, y_min: fixed, y_max: free}
probes:
  - {name: toe, body: column, position: [0.095, 0.005]}
  - {name: top, body: column, position: [0.005, 0.195]}
output: {every: 0.02, probe_every: 0.005, grid: true}
threads: 1
)";

ProcessResult run_mpm(const fs::path& config, const fs::path& output, int ranks) {
  return run_launched("mpm_solver", config, output, ranks);
}

TEST(MpmSolverRanks, EveryRankCountWritesTheFilesOfOneProcess) {
  const fs::path dir = fresh_directory("mpm_solver_ranks");
  const fs::path config = write_case(dir, column_case);
  const ProcessResult whole = run_mpm(config, dir / "one_process", 0);
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const auto reference = nlohmann::json::parse(read_text(dir / "one_process" / "summary.json"));
  const std::size_t snapshots = reference["metrics"]["snapshots"]["value"].get<std::size_t>();
  ASSERT_EQ(snapshots, 4u);
  double rebalances = 0.0;
  for (int ranks : {2, 3, 4}) {
    const fs::path out = dir / ("ranks_" + std::to_string(ranks));
    const ProcessResult split = run_mpm(config, out, ranks);
    ASSERT_EQ(split.exit_code, 0) << split.output;
    for (const char* file : {"particles.xdmf", "grid.xdmf", "probes.csv"})
      EXPECT_EQ(read_text(out / file), read_text(dir / "one_process" / file))
          << file << " on " << ranks << " ranks";
    for (std::size_t s = 0; s < snapshots; ++s)
      for (const char* base : {"particles", "grid"}) {
        const std::string file = fmt::format("{}_{:06d}.h5", base, s);
        EXPECT_EQ(hdf5_contents(out / file), hdf5_contents(dir / "one_process" / file))
            << file << " on " << ranks << " ranks";
      }
    const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
    EXPECT_EQ(summary["steps"], reference["steps"]);
    EXPECT_EQ(summary["case"]["ranks"], ranks);
    rebalances += summary["metrics"]["rebalances"]["value"].get<double>();
    EXPECT_GE(summary["metrics"]["point_imbalance_max"]["value"].get<double>(), 1.0);
    EXPECT_EQ(summary["metrics"]["particles"]["value"], reference["metrics"]["particles"]["value"]);
    const double scale =
        std::abs(reference["conserved"]["gravitational_energy"]["end"].get<double>());
    for (const char* quantity : {"mass", "momentum_x", "momentum_y", "kinetic_energy",
                                 "strain_energy", "plastic_dissipation", "energy_balance"})
      for (const char* when : {"start", "end"})
        EXPECT_NEAR(summary["conserved"][quantity][when].get<double>(),
                    reference["conserved"][quantity][when].get<double>(), 1e-12 * scale)
            << quantity << " at the " << when << " on " << ranks << " ranks";
    for (int r = 1; r < ranks; ++r)
      EXPECT_TRUE(fs::exists(out / "ranks" / ("rank_" + std::to_string(r)) / "log.txt"));
  }
  // The column settles into the lower rows: the cuts moved on the way, and
  // the files above were still those of one process.
  EXPECT_GE(rebalances, 1.0);
}

void expect_refused(const std::string& case_text, const std::string& key, int ranks) {
  expect_refused_on_ranks("mpm_solver", case_text, key, ranks, "particles_000000.h5");
}

TEST(MpmSolverRanks, RefusesMoreRanksThanSlabs) {
  // 25 rows make 7 slabs of 4 rows: not enough for 8 ranks.
  expect_refused(column_case, "grid.cells", 8);
}

TEST(MpmSolverRanks, LeavesAnOutputDirectoryInUseAsItWas) {
  expect_directory_in_use_kept("mpm_solver", column_case);
}

// Standalone windows of 0.01 s, each run twice (--cosim-repeat-windows):
// every rank saves its points at a window's start and puts them back, the
// cuts move only between windows, and the files are those of one process.
TEST(MpmSolverRanks, WindowsThatRunAgainKeepTheFilesOfOneProcess) {
  const fs::path dir = fresh_directory("mpm_solver_ranks_windows");
  const fs::path config = write_case(
      dir, replaced(column_case, "safety_factor: 0.4}", "safety_factor: 0.4, window: 0.01}"));
  const auto run_on = [&](int ranks, const fs::path& out) {
    std::vector<std::string> args;
    if (ranks > 0) args = {MPIEXEC, "--oversubscribe", "-np", std::to_string(ranks)};
    for (const std::string& a :
         {binary("mpm_solver").string(), std::string("--config"), config.string(),
          std::string("--output"), out.string(), std::string("--cosim-repeat-windows")})
      args.push_back(a);
    return run(args, std::chrono::seconds(120));
  };
  const fs::path one = dir / "one_process";
  const ProcessResult whole = run_on(0, one);
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const auto reference = nlohmann::json::parse(read_text(one / "summary.json"));
  EXPECT_EQ(reference["metrics"]["state_restores"]["value"], 6.0);
  double rebalances = 0.0;
  for (int ranks : {2, 3}) {
    const fs::path out = dir / ("ranks_" + std::to_string(ranks));
    const ProcessResult split = run_on(ranks, out);
    ASSERT_EQ(split.exit_code, 0) << split.output;
    EXPECT_EQ(read_text(out / "probes.csv"), read_text(one / "probes.csv")) << ranks << " ranks";
    for (int s = 0; s < 4; ++s) {
      const std::string file = fmt::format("particles_{:06d}.h5", s);
      EXPECT_EQ(hdf5_contents(out / file), hdf5_contents(one / file))
          << file << " on " << ranks << " ranks";
    }
    const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
    EXPECT_EQ(summary["steps"], reference["steps"]);
    EXPECT_EQ(summary["metrics"]["state_restores"], reference["metrics"]["state_restores"]);
    rebalances += summary["metrics"]["rebalances"]["value"].get<double>();
  }
  EXPECT_GE(rebalances, 1.0);
}

// configs/ice_coupled/<job>: the job shortened to `end_time` over MPI, with
// the soil and the water on the ranks given, written into `dir` with the
// participants' configs; the water solves its pressure with PETSc when
// `petsc` (both ways alike whatever its ranks).
struct CoupledJob {
  std::string source, job_file, end_time, soil, water;
  bool petsc = false;
  // Grids refined to this many cells a side (0: as they are), with the
  // window the finer exchange cells need.
  int cells = 0;
  std::string window = {};
};

fs::path write_coupled_job(const fs::path& dir, const CoupledJob& job, const std::string& end_time,
                           int soil_ranks, int water_ranks) {
  const fs::path source = fs::path(COSIM_SOURCE_DIR) / "configs/ice_coupled" / job.source;
  fs::create_directories(dir);
  std::string text = replaced(read_text(source / job.job_file), "end_time: " + job.end_time + "\n",
                              "end_time: " + end_time + "\ntransport: mpi\n");
  text = replaced(text, "    config: " + job.soil + "\n",
                  fmt::format("    config: {}\n    ranks: {}\n", job.soil, soil_ranks));
  text = replaced(text, "    config: " + job.water + "\n",
                  fmt::format("    config: {}\n    ranks: {}\n", job.water, water_ranks));
  std::string water = read_text(source / job.water);
  std::string soil = read_text(source / job.soil);
  if (job.petsc) water = replaced(water, "numerics:\n", "numerics:\n  pressure: {solver: petsc}\n");
  if (job.cells > 0) {
    const std::string cells = fmt::format("cells: [{0}, {0}]", job.cells);
    water = replaced(water, "cells: [8, 8]", cells);
    soil = replaced(soil, "cells: [8, 8]", cells);
    text = replaced(text, "window: 5.0e-5", "window: " + job.window);
  }
  write_text(dir / "job.yaml", text);
  write_text(dir / job.water, water);
  write_text(dir / job.soil, soil);
  return dir / "job.yaml";
}

// Terzaghi's consolidation (soil and water on 2 ranks each), the clay
// column (soil on 2 ranks, its 8 x 8 water too narrow for two blocks of 5
// ghost layers), the clay column refined to 16 x 16 (both on 2 ranks) and
// the thermal cavity (grains on 2 ranks, heat exchanged both ways),
// shortened, against the same jobs on one process each: the soil's points
// sum their exchange-grid shares over the ranks before the fields are
// formed, and take their shares of what the water sends from sums over the
// ranks too. The snapshots and gauges agree to the pressure solver's
// tolerance (1e-8 with PETSc), or to round-off with the serial one; mass and
// the impulse the soil took agree to round-off.
TEST(MpmSolverRanks, ACoupledSoilOnTwoRanksGivesTheOneProcessRun) {
  struct Case {
    CoupledJob job;
    int water_ranks;
    std::string name, snapshot;
    double tolerance;
    std::string end_time = "0.01", soil_name = "soil";
  };
  // The refined column runs to 0.01 s only: near 0.019 s a perturbation of
  // 1e-12 (of Young's modulus, on one process) already moves its soil by
  // 1 % (something discrete happens there; not investigated yet).
  const Case cases[] = {
      {{"terzaghi", "job.yaml", "0.75", "soil.yaml", "water.yaml", true},
       2,
       "terzaghi",
       "000001",
       1e-8},
      {{".", "job.yaml", "0.1", "soil_column.yaml", "water.yaml"},
       1,
       "clay_column",
       "000002",
       1e-10,
       "0.02"},
      {{".", "job.yaml", "0.1", "soil_column.yaml", "water.yaml", true, 16, "2.5e-5"},
       2,
       "clay_column_16",
       "000001",
       1e-8},
      // Heat exchanged both ways: the grains' heat conduction and thermal
      // fields on ranks (the water's decomposed pressure solve alone moves
      // its slow convection, 2e-6 m/s, by 1e-4 relative, as a tolerance of
      // 1e-12 instead of 1e-10 does on one process: it stays on one).
      {{"thermal_cavity", "job.yaml", "5.0e7", "grains.yaml", "water.yaml", true},
       1,
       "thermal_cavity",
       "000001",
       1e-10,
       "2.5e6",
       "grains"}};
  for (const Case& c : cases) {
    const std::string& name = c.name;
    SCOPED_TRACE(name);
    const fs::path dir = fresh_directory("mpm_solver_coupled_ranks_" + name);
    const std::string& end_time = c.end_time;
    for (const auto& [soil_ranks, water_ranks] : {std::pair{1, 1}, std::pair{2, c.water_ranks}}) {
      const fs::path run_dir = dir / fmt::format("soil_{}", soil_ranks);
      const fs::path job = write_coupled_job(run_dir, c.job, end_time, soil_ranks, water_ranks);
      const ProcessResult result = cosim_run(job, run_dir / "run", 240);
      ASSERT_EQ(result.exit_code, 0) << result.output << read_text(run_dir / "run" / "mpirun.log");
    }
    const fs::path one = dir / "soil_1" / "run";
    const fs::path two = dir / "soil_2" / "run";
    const fs::path soil = c.soil_name;
    const auto summary_one = nlohmann::json::parse(read_text(one / soil / "summary.json"));
    const auto summary_two = nlohmann::json::parse(read_text(two / soil / "summary.json"));
    EXPECT_EQ(summary_two["case"]["ranks"], 2);
    double worst = 0.0;
    {
      const Hdf5Reader a(one / "water" / ("ice_" + c.snapshot + ".h5")),
          b(two / "water" / ("ice_" + c.snapshot + ".h5"));
      for (const char* field : {"pressure", "velocity_water", "bulk_density_water",
                                "volume_fraction_water", "temperature_water"})
        worst = std::max(worst, relative_difference(a, b, std::string("fields/") + field));
    }
    {
      const Hdf5Reader a(one / soil / ("particles_" + c.snapshot + ".h5")),
          b(two / soil / ("particles_" + c.snapshot + ".h5"));
      for (const char* field : {"velocity", "stress", "pore_pressure", "displacement"})
        worst = std::max(worst, relative_difference(a, b, std::string("fields/") + field));
      if (c.soil_name == "grains")
        worst = std::max(worst, relative_difference(a, b, "fields/temperature"));
    }
    const bool gauged = fs::exists(one / "water" / "gauges.csv");
    const auto gauges_one =
        gauged ? read_csv(one / "water" / "gauges.csv") : std::vector<std::vector<double>>{};
    const auto gauges_two =
        gauged ? read_csv(two / "water" / "gauges.csv") : std::vector<std::vector<double>>{};
    ASSERT_EQ(gauges_one.size(), gauges_two.size());
    for (std::size_t i = 0; i < gauges_one.size(); ++i)
      for (std::size_t k = 0; k < gauges_one[i].size(); ++k)
        worst = std::max(worst, std::abs(gauges_one[i][k] - gauges_two[i][k]) /
                                    std::max(1.0, std::abs(gauges_one[i][k])));
    std::printf(
        "%s: soil on 2 ranks, water on %d, against 1 process each: worst relative "
        "difference %.2e (tolerance %.0e)\n",
        name.c_str(), c.water_ranks, worst, c.tolerance);
    EXPECT_LE(worst, c.tolerance);
    EXPECT_NEAR(summary_two["conserved"]["mass"]["end"].get<double>(),
                summary_one["conserved"]["mass"]["end"].get<double>(),
                1e-12 * summary_one["conserved"]["mass"]["end"].get<double>());
    const auto applied_one = summary_one["coupling"]["impulse_applied"].get<std::vector<double>>();
    const auto applied_two = summary_two["coupling"]["impulse_applied"].get<std::vector<double>>();
    ASSERT_EQ(applied_one.size(), applied_two.size());
    double impulse = 0.0;
    for (double component : applied_one) impulse = std::max(impulse, std::abs(component));
    for (std::size_t k = 0; k < applied_one.size(); ++k)
      EXPECT_NEAR(applied_two[k], applied_one[k], c.tolerance * impulse) << "component " << k;
    const double heat_one = summary_one["coupling"]["heat_applied"].get<double>();
    const double heat_two = summary_two["coupling"]["heat_applied"].get<double>();
    EXPECT_NEAR(heat_two, heat_one, 1e-8 * std::max(1.0, std::abs(heat_one)));
  }
}

// The clay column (soil on 2 ranks, water on 1) with checkpoints: the run
// continued from one on the same ranks writes what the uninterrupted run
// wrote after it, bit for bit; each rank wrote its points, and the soil
// restarts on another count of ranks too (its points read from every part
// and sent to the ranks that own them now, this library's fields joined
// from the parts and split again), here 1 and 2 from checkpoints of 2 and
// 1: the same last snapshots, since the soil's ranks give the one-process
// run bit for bit. Terzaghi's consolidation with the water on 2 ranks too
// continues bit for bit on the same ranks, and on 1 and 3 ranks each to the
// pressure solver's tolerance.
TEST(MpmSolverRanks, ACoupledSoilContinuesFromItsCheckpointOnAnyCountOfRanks) {
  const fs::path dir = fresh_directory("mpm_solver_coupled_ranks_restart");
  const CoupledJob column{".", "job.yaml", "0.1", "soil_column.yaml", "water.yaml"};
  const fs::path on_two = write_coupled_job(dir / "two", column, "0.02", 2, 1);
  expect_restart_continues(dir / "two", on_two, "200", 200);
  const fs::path checkpoint_of_two = checkpoint_of(dir / "two" / "whole", 200);
  EXPECT_TRUE(fs::exists(checkpoint_of_two / "soil" / "rank_1" / "state.h5"));

  const fs::path on_one = write_coupled_job(dir / "one", column, "0.02", 1, 1);
  const ProcessResult from_two =
      cosim_run(on_one, dir / "one" / "from_two", 120, {"--restart", checkpoint_of_two.string()});
  ASSERT_EQ(from_two.exit_code, 0) << from_two.output;
  EXPECT_EQ(expect_same_last_snapshots(dir / "two" / "whole", dir / "one" / "from_two"), 2u);

  const ProcessResult whole_one =
      cosim_run(on_one, dir / "one" / "whole", 120, {"--checkpoint-every", "200"});
  ASSERT_EQ(whole_one.exit_code, 0) << whole_one.output;
  const ProcessResult from_one =
      cosim_run(on_two, dir / "two" / "from_one", 120,
                {"--restart", checkpoint_of(dir / "one" / "whole", 200).string()});
  ASSERT_EQ(from_one.exit_code, 0) << from_one.output;
  EXPECT_EQ(expect_same_last_snapshots(dir / "one" / "whole", dir / "two" / "from_one"), 2u);
  const auto summary =
      nlohmann::json::parse(read_text(dir / "two" / "from_one" / "soil" / "summary.json"));
  EXPECT_EQ(summary["case"]["ranks"], 2);

  // Terzaghi with the water on 2 ranks too (PETSc): each water rank its block.
  const CoupledJob terzaghi{"terzaghi", "job.yaml", "0.75", "soil.yaml", "water.yaml", true};
  expect_restart_continues(
      dir / "terzaghi", write_coupled_job(dir / "terzaghi", terzaghi, "0.004", 2, 2), "200", 200);
  const fs::path checkpoint = checkpoint_of(dir / "terzaghi" / "whole", 200);
  EXPECT_TRUE(fs::exists(checkpoint / "water" / "rank_1" / "state.h5"));
  // On 1 and on 3 ranks each (the water's blocks joined from the two that
  // wrote it, cells and faces): the last snapshots of the uninterrupted run,
  // to the pressure solver's tolerance (its sums change with the ranks).
  const auto last_snapshot = [](const fs::path& directory, const std::string& prefix) {
    fs::path last;
    for (const auto& entry : fs::directory_iterator(directory)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind(prefix, 0) == 0 && entry.path().extension() == ".h5" &&
          (last.empty() || name > last.filename().string()))
        last = entry.path();
    }
    return last;
  };
  for (const int ranks : {1, 3}) {
    const fs::path run_dir = dir / fmt::format("terzaghi_on_{}", ranks);
    const ProcessResult r = cosim_run(write_coupled_job(run_dir, terzaghi, "0.004", ranks, ranks),
                                      run_dir / "run", 240, {"--restart", checkpoint.string()});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    double worst = 0.0;
    {
      const Hdf5Reader a(last_snapshot(dir / "terzaghi" / "whole" / "water", "ice_")),
          b(last_snapshot(run_dir / "run" / "water", "ice_"));
      for (const char* field : {"pressure", "velocity_water", "bulk_density_water"})
        worst = std::max(worst, relative_difference(a, b, std::string("fields/") + field));
    }
    {
      const Hdf5Reader a(last_snapshot(dir / "terzaghi" / "whole" / "soil", "particles_")),
          b(last_snapshot(run_dir / "run" / "soil", "particles_"));
      for (const char* field : {"velocity", "stress", "pore_pressure", "displacement"})
        worst = std::max(worst, relative_difference(a, b, std::string("fields/") + field));
    }
    std::printf(
        "Terzaghi restarted from 2 + 2 ranks on %d + %d: worst relative difference %.2e "
        "(tolerance 1e-8)\n",
        ranks, ranks, worst);
    EXPECT_LE(worst, 1e-8);
  }
}

// A soil that cannot start on its ranks (the Darcy column's one cell row
// cannot be cut in two), or on its one rank (a bad case), fails before it
// says hello to the coupler: it ends the MPI job itself at once, and
// `cosim run` exits with 2 naming the participant and the key.
TEST(MpmSolverRanks, ASoilThatCannotStartEndsTheCoupledJobAtOnceWithExit2) {
  const fs::path dir = fresh_directory("mpm_solver_coupled_cannot_start");
  {
    const CoupledJob darcy{"darcy", "job.yaml", "0.3", "column.yaml", "water.yaml"};
    const fs::path job = write_coupled_job(dir / "darcy", darcy, "0.01", 2, 1);
    const auto started = std::chrono::steady_clock::now();
    const ProcessResult r = cosim_run(job, dir / "darcy" / "run", 60);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr("participant 'column' failed before the coupling began"));
    EXPECT_THAT(r.output, HasSubstr("key 'grid.cells'"));
    const auto summary = nlohmann::json::parse(read_text(dir / "darcy" / "run" / "summary.json"));
    EXPECT_EQ(summary["status"]["exit_code"], 2);
    std::printf("the Darcy soil on 2 ranks was refused in %.1f s\n", seconds);
    // Well inside the connect timeout (120 s) the coupler would otherwise wait.
    EXPECT_LT(seconds, 60.0);
  }
  {
    const CoupledJob column{".", "job.yaml", "0.1", "soil_column.yaml", "water.yaml"};
    const fs::path job = write_coupled_job(dir / "bad_case", column, "0.02", 1, 1);
    write_text(dir / "bad_case" / "soil_column.yaml",
               replaced(read_text(dir / "bad_case" / "soil_column.yaml"), "cells: [8, 8]",
                        "cells: [8, -8]"));
    const ProcessResult r = cosim_run(job, dir / "bad_case" / "run", 60);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr("participant 'soil' failed before the coupling began"));
    EXPECT_THAT(r.output, HasSubstr("soil_column.yaml:8:"));
  }
}

}  // namespace
}  // namespace cosim::testing
