// ice_fluid standalone under `mpirun -np N` (label mpi): a dam break in air,
// on 1 process with the built-in pressure solver and on 2, 3 and 4 ranks
// with PETSc's, must write the same files: the XDMF index as it is, every
// snapshot field and gauge to the pressure solvers' tolerance, the same
// steps, the totals to round-off; on one process `solver: petsc` gives the same too.
// Cases a decomposed run cannot take, and an output directory already in
// use, are refused with exit 2 by every rank, nothing lost. Coupled over MPI,
// a water on 2 ranks gives the one-process run's results, and a water too
// narrow for its ranks ends the job at once with exit 2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "demo_job.hpp"
#include "hdf5_reader.hpp"
#include "launched_program.hpp"
#include "replaced_text.hpp"
#include "run_process.hpp"
#include "snapshot_difference.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

constexpr const char* dam_break_case = R"(kind: ice_case
name: dam_break
dimension: 2
grid: {origin: [0.0, 0.0], upper: [0.28575, 0.142875], cells: [40, 20]}
gravity: [0.0, -9.81]
end_time: 0.03
materials:
  water:
    eos: {type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8}
    viscosity: 1.0e-3
  air:
    eos: {type: ideal_gas, gas_constant: 287.0, heat_capacity_ratio: 1.4}
    viscosity: 1.8e-5
exchange:
  - {materials: [water, air], momentum: 1.0e15}
initial:
  fill: air
  pressure: hydrostatic
  temperature: 293.15
  regions:
    - {box: {lower: [0.0, 0.0], upper: [0.1, 0.1143]}, fill: water}
boundaries:
  y_max: {type: fixed_pressure, pressure: 101325}
numerics:
  pressure: {tolerance: 1.0e-12}
output:
  every: 0.01
  gauges:
    - {name: wall, point: [0.2, 0.01]}
    - {name: corner, point: [0.01, 0.01]}
  wave_gauges:
    - {name: surge, point: [0.12, 0.0]}
)";

const std::vector<std::string> snapshots{"ice_000000.h5", "ice_000001.h5", "ice_000002.h5",
                                         "ice_000003.h5"};
const std::vector<std::string> fields{"pressure",         "density",
                                      "velocity",         "bulk_density_water",
                                      "bulk_density_air", "temperature_water",
                                      "velocity_water",   "velocity_air",
                                      "density_water",    "volume_fraction_water"};

// max over the snapshots and fields of |run - reference| / max |reference|.
double worst_difference(const fs::path& run, const fs::path& reference) {
  double worst = 0.0;
  for (const std::string& snapshot : snapshots) {
    const Hdf5Reader mine(run / snapshot), theirs(reference / snapshot);
    for (const std::string& field : fields) {
      const auto a = mine.doubles("fields/" + field);
      const auto b = theirs.doubles("fields/" + field);
      EXPECT_EQ(a.dims, b.dims) << field;
      if (a.values.size() != b.values.size()) return 1.0;
      double scale = 0.0, difference = 0.0;
      for (std::size_t i = 0; i < b.values.size(); ++i) {
        scale = std::max(scale, std::abs(b.values[i]));
        difference = std::max(difference, std::abs(a.values[i] - b.values[i]));
      }
      worst = std::max(worst, difference / scale);
    }
  }
  return worst;
}

void expect_same_run(const fs::path& run, const fs::path& reference, const std::string& what,
                     int ranks) {
  const double worst = worst_difference(run, reference);
  std::printf("ice_fluid %s: worst relative difference of the snapshots %.3g (tolerance 1e-8)\n",
              what.c_str(), worst);
  EXPECT_LT(worst, 1e-8) << what;
  EXPECT_EQ(read_text(run / "ice.xdmf"), read_text(reference / "ice.xdmf")) << what;
  const auto summary = nlohmann::json::parse(read_text(run / "summary.json"));
  const auto expected = nlohmann::json::parse(read_text(reference / "summary.json"));
  EXPECT_EQ(summary["steps"], expected["steps"]) << what;
  EXPECT_EQ(summary["case"]["ranks"], ranks) << what;
  EXPECT_EQ(summary["case"]["pressure_solver"], "petsc") << what;
  for (const char* quantity : {"mass_water", "mass_air"})
    for (const char* when : {"start", "end"}) {
      const double reference_value = expected["conserved"][quantity][when].get<double>();
      EXPECT_NEAR(summary["conserved"][quantity][when].get<double>(), reference_value,
                  1e-13 * reference_value)
          << quantity << " at the " << when << ", " << what;
    }
  EXPECT_EQ(read_csv(run / "steps.csv").size(), read_csv(reference / "steps.csv").size()) << what;
  // The gauges and the wave gauge's column: each value to the solvers' tolerance against its
  // column's largest.
  const auto gauges = read_csv(run / "gauges.csv");
  const auto expected_gauges = read_csv(reference / "gauges.csv");
  ASSERT_EQ(gauges.size(), expected_gauges.size()) << what;
  ASSERT_FALSE(gauges.empty());
  double worst_gauge = 0.0;
  for (std::size_t column = 0; column < gauges[0].size(); ++column) {
    double scale = 0.0, difference = 0.0;
    for (std::size_t row = 0; row < gauges.size(); ++row) {
      scale = std::max(scale, std::abs(expected_gauges[row][column]));
      difference =
          std::max(difference, std::abs(gauges[row][column] - expected_gauges[row][column]));
    }
    if (scale > 0.0) worst_gauge = std::max(worst_gauge, difference / scale);
  }
  std::printf("ice_fluid %s: worst relative difference of gauges.csv %.3g (tolerance 1e-8)\n",
              what.c_str(), worst_gauge);
  EXPECT_LT(worst_gauge, 1e-8) << what;
  EXPECT_EQ(read_text(run / "gauges.csv").substr(0, 200),
            read_text(reference / "gauges.csv").substr(0, 200));
}

TEST(IceFluidRanks, EveryRankCountWritesTheFilesOfOneProcess) {
  const fs::path dir = fresh_directory("ice_fluid_ranks");
  const fs::path config = write_case(dir, dam_break_case);
  const ProcessResult whole = run_launched("ice_fluid", config, dir / "one_process", 0);
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  for (int ranks : {2, 3, 4}) {
    const fs::path out = dir / ("ranks_" + std::to_string(ranks));
    const ProcessResult split = run_launched("ice_fluid", config, out, ranks);
    ASSERT_EQ(split.exit_code, 0) << split.output;
    expect_same_run(out, dir / "one_process", std::to_string(ranks) + " ranks", ranks);
    for (int r = 1; r < ranks; ++r)
      EXPECT_TRUE(fs::exists(out / "ranks" / ("rank_" + std::to_string(r)) / "log.txt"));
  }
  // PETSc on one process, asked for by the case.
  const fs::path petsc_config =
      write_case(dir / "petsc", replaced(dam_break_case, "pressure: {tolerance: 1.0e-12}",
                                         "pressure: {tolerance: 1.0e-12, solver: petsc, "
                                         "preconditioner: boomeramg}"));
  const ProcessResult petsc = run_launched("ice_fluid", petsc_config, dir / "petsc" / "run", 0);
  ASSERT_EQ(petsc.exit_code, 0) << petsc.output;
  expect_same_run(dir / "petsc" / "run", dir / "one_process", "one process, PETSc", 1);
}

// Standalone windows of 5 ms, each run twice (--cosim-repeat-windows): every
// rank saves its block at a window's start and puts it back, and the run is
// the one-process run's (PETSc both ways) to the solver's tolerance.
TEST(IceFluidRanks, WindowsThatRunAgainOnRanksGiveTheOneProcessRun) {
  const fs::path dir = fresh_directory("ice_fluid_ranks_windows");
  const fs::path config = write_case(
      dir,
      replaced(replaced(dam_break_case, "end_time: 0.03", "end_time: 0.03\nwindow: 0.005"),
               "pressure: {tolerance: 1.0e-12}", "pressure: {tolerance: 1.0e-12, solver: petsc}"));
  const ProcessResult whole =
      run_launched("ice_fluid", config, dir / "one_process", 0, {"--cosim-repeat-windows"});
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const ProcessResult split =
      run_launched("ice_fluid", config, dir / "ranks_2", 2, {"--cosim-repeat-windows"});
  ASSERT_EQ(split.exit_code, 0) << split.output;
  expect_same_run(dir / "ranks_2", dir / "one_process", "2 ranks, windows run twice", 2);
  const auto summary = nlohmann::json::parse(read_text(dir / "ranks_2" / "summary.json"));
  EXPECT_EQ(summary["windows"], 6);
  EXPECT_TRUE(summary["wall_time_s"]["phases"].contains("restore_state"));
}

void expect_refused(const std::string& case_text, const std::string& key, int ranks) {
  expect_refused_on_ranks("ice_fluid", case_text, key, ranks, "ice_000000.h5");
}

TEST(IceFluidRanks, RefusesBlocksNarrowerThanTheGhostLayers) {
  expect_refused(replaced(dam_break_case, "cells: [40, 20]", "cells: [8, 4]"), "grid.cells", 2);
}

TEST(IceFluidRanks, RefusesWhatADecomposedRunCannotTakeYet) {
  expect_refused(replaced(dam_break_case, "pressure: {tolerance: 1.0e-12}",
                          "pressure: {tolerance: 1.0e-12, solver: builtin}"),
                 "numerics.pressure.solver", 2);
  expect_refused(read_text(fs::path(COSIM_SOURCE_DIR) / "configs/ice/sod_shock_tube.yaml"),
                 "dimension", 2);
}

// `solver: petsc` on one process of an MPMD coupled job (the Darcy column
// over the MPI transport): PETSc takes this process alone, starts after the
// transport and ends before it; the fields are the built-in solver's.
TEST(IceFluidRanks, PetscOnOneProcessOfACoupledJobOverMpi) {
  const fs::path dir = fresh_directory("ice_fluid_petsc_coupled");
  const fs::path darcy = fs::path(COSIM_SOURCE_DIR) / "configs/ice_coupled/darcy";
  const std::string job =
      replaced(read_text(darcy / "job.yaml"), "end_time: 0.3", "end_time: 0.01\ntransport: mpi");
  write_text(dir / "column.yaml", read_text(darcy / "column.yaml"));
  const std::string water = read_text(darcy / "water.yaml");
  write_text(dir / "water.yaml", water);
  write_text(dir / "petsc" / "water.yaml",
             replaced(water, "  initial_time_step: 1.0e-4\n",
                      "  initial_time_step: 1.0e-4\n  pressure: {solver: petsc}\n"));
  write_text(dir / "petsc" / "column.yaml", read_text(darcy / "column.yaml"));
  write_text(dir / "job.yaml", job);
  write_text(dir / "petsc" / "job.yaml", job);
  for (const fs::path& run_dir : {dir, dir / "petsc"}) {
    const ProcessResult result =
        run({binary("cosim").string(), "run", (run_dir / "job.yaml").string(), "--output",
             (run_dir / "run").string()},
            std::chrono::seconds(120));
    ASSERT_EQ(result.exit_code, 0) << result.output << read_text(run_dir / "run" / "mpirun.log");
  }
  const auto summary = nlohmann::json::parse(read_text(dir / "petsc/run/water/summary.json"));
  EXPECT_EQ(summary["case"]["pressure_solver"], "petsc");
  const Hdf5Reader mine(dir / "petsc/run/water/ice_000001.h5");
  const Hdf5Reader theirs(dir / "run/water/ice_000001.h5");
  for (const char* field : {"pressure", "velocity_water"}) {
    const auto a = mine.doubles(std::string("fields/") + field);
    const auto b = theirs.doubles(std::string("fields/") + field);
    ASSERT_EQ(a.values.size(), b.values.size());
    double scale = 0.0, difference = 0.0;
    for (std::size_t i = 0; i < b.values.size(); ++i) {
      scale = std::max(scale, std::abs(b.values[i]));
      difference = std::max(difference, std::abs(a.values[i] - b.values[i]));
    }
    EXPECT_LT(difference, 1e-8 * scale) << field;
  }
}

// A coupled job over MPI whose water (ice_fluid) runs on 2 ranks, a
// partitioned participant: the Darcy column and Terzaghi's consolidation
// (configs/ice_coupled), shortened, against the same jobs with the water on
// one process (PETSc there too, so that both solve the pressure alike). The
// water's snapshots and the soil's, and the gauges, agree to the pressure
// solver's tolerance.
TEST(IceFluidRanks, ACoupledWaterOnTwoRanksGivesTheOneProcessRun) {
  struct Job {
    std::string name, end_time, soil, soil_snapshot;
  };
  for (const Job& job : {Job{"darcy", "0.3", "column", "particles_000001.h5"},
                         Job{"terzaghi", "0.75", "soil", "particles_000001.h5"}}) {
    SCOPED_TRACE(job.name);
    const fs::path source = fs::path(COSIM_SOURCE_DIR) / "configs/ice_coupled" / job.name;
    const fs::path dir = fresh_directory("ice_fluid_coupled_ranks_" + job.name);
    for (const int ranks : {1, 2}) {
      const fs::path run_dir = dir / fmt::format("ranks_{}", ranks);
      fs::create_directories(run_dir);
      std::string text = replaced(read_text(source / "job.yaml"), "end_time: " + job.end_time,
                                  "end_time: 0.01\ntransport: mpi");
      text = replaced(text, "    config: water.yaml\n",
                      fmt::format("    config: water.yaml\n    ranks: {}\n", ranks));
      write_text(run_dir / "job.yaml", text);
      write_text(run_dir / "water.yaml", replaced(read_text(source / "water.yaml"), "numerics:\n",
                                                  "numerics:\n  pressure: {solver: petsc}\n"));
      for (const auto& entry : fs::directory_iterator(source))
        if (entry.path().filename() != "job.yaml" && entry.path().filename() != "water.yaml")
          fs::copy_file(entry.path(), run_dir / entry.path().filename());
      const ProcessResult result = cosim_run(run_dir / "job.yaml", run_dir / "run", 240);
      ASSERT_EQ(result.exit_code, 0) << result.output << read_text(run_dir / "run" / "mpirun.log");
    }
    const fs::path one = dir / "ranks_1" / "run";
    const fs::path two = dir / "ranks_2" / "run";
    EXPECT_EQ(nlohmann::json::parse(read_text(two / "water" / "summary.json"))["case"]["ranks"], 2);
    double worst = 0.0;
    {
      const Hdf5Reader a(one / "water" / "ice_000001.h5"), b(two / "water" / "ice_000001.h5");
      for (const char* field : {"pressure", "velocity_water", "bulk_density_water",
                                "volume_fraction_water", "temperature_water"})
        worst = std::max(worst, relative_difference(a, b, std::string("fields/") + field));
    }
    {
      const Hdf5Reader a(one / job.soil / job.soil_snapshot), b(two / job.soil / job.soil_snapshot);
      for (const char* field : {"velocity", "stress", "pore_pressure", "displacement"})
        worst = std::max(worst, relative_difference(a, b, std::string("fields/") + field));
    }
    const auto gauges_one = read_csv(one / "water" / "gauges.csv");
    const auto gauges_two = read_csv(two / "water" / "gauges.csv");
    ASSERT_EQ(gauges_one.size(), gauges_two.size());
    for (std::size_t i = 0; i < gauges_one.size(); ++i)
      for (std::size_t k = 0; k < gauges_one[i].size(); ++k)
        worst = std::max(worst, std::abs(gauges_one[i][k] - gauges_two[i][k]) /
                                    std::max(1.0, std::abs(gauges_one[i][k])));
    std::printf("%s: water on 2 ranks against 1 process: worst relative difference %.2e\n",
                job.name.c_str(), worst);
    EXPECT_LE(worst, 1e-8);
  }
}

// The clay column's 8 x 8 water cannot be cut into two blocks of 5 ghost
// layers: refused before it says hello to the coupler, it ends the MPI job
// itself, and `cosim run` exits with 2 at once, naming it and the key.
TEST(IceFluidRanks, AWaterTooNarrowForItsRanksEndsTheCoupledJobAtOnceWithExit2) {
  const fs::path source = fs::path(COSIM_SOURCE_DIR) / "configs/ice_coupled";
  const fs::path dir = fresh_directory("ice_fluid_coupled_too_narrow");
  std::string text = replaced(read_text(source / "job.yaml"), "end_time: 0.1\n",
                              "end_time: 0.01\ntransport: mpi\n");
  text = replaced(text, "    config: water.yaml\n", "    config: water.yaml\n    ranks: 2\n");
  write_text(dir / "job.yaml", text);
  for (const char* file : {"water.yaml", "soil_column.yaml"})
    fs::copy_file(source / file, dir / file);
  const auto started = std::chrono::steady_clock::now();
  const ProcessResult r = cosim_run(dir / "job.yaml", dir / "run", 60);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("participant 'water' failed before the coupling began"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("key 'grid.cells'"), std::string::npos) << r.output;
  std::printf("the water on 2 ranks was refused in %.1f s\n", seconds);
  EXPECT_LT(seconds, 60.0);  // the coupler's connect timeout is 120 s
}

TEST(IceFluidRanks, LeavesAnOutputDirectoryInUseAsItWas) {
  expect_directory_in_use_kept("ice_fluid", dam_break_case);
}

}  // namespace
}  // namespace cosim::testing
