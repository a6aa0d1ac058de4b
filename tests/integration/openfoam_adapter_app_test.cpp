// openfoam_adapter end to end: its bad-input exits (which need no OpenFOAM),
// then, with OpenFOAM installed, a small generated case run window by
// window, a failing OpenFOAM run and a coupled job whose windows repeat. Without OpenFOAM the
// executable exits 77 after the first group, which CTest reports as not run (SKIP_RETURN_CODE),
// printing why.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cosim/error.hpp"
#include "hdf5_contents.hpp"
#include "openfoam/foam/installation.hpp"
#include "openfoam/foam/time_directories.hpp"
#include "openfoam/io/case_layout.hpp"
#include "replaced_text.hpp"
#include "restart_continuation.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace {

namespace fs = std::filesystem;
using cosim::testing::binary;
using cosim::testing::checkpoint_of;
using cosim::testing::expect_restart_continues;
using cosim::testing::fresh_directory;
using cosim::testing::hdf5_contents;
using cosim::testing::read_text;
using cosim::testing::replaced;
using cosim::testing::run_job;
using cosim::testing::write_text;

bool openfoam_installed = false;

const std::string small_tank = R"(kind: openfoam_case
name: tank
generate:
  dimension: 2
  grid: {origin: [0.0, 0.0], upper: [0.2, 0.1], cells: [10, 5]}
  gravity: [0.0, -9.81]
  fluids:
    water: {density: 1000, viscosity: 1.0e-3}
    air: {density: 1, viscosity: 1.8e-5}
  water:
    - box: {lower: [0.0, 0.0], upper: [0.06, 0.06]}
  boundaries: {y_max: atmosphere}
end_time: 0.02
time_step: 1.0e-3
window: 0.005
output: {every: 0.01}
)";

cosim::testing::ProcessResult run_adapter(const fs::path& config, const fs::path& output,
                                          std::vector<std::string> prefix = {}) {
  prefix.push_back(binary("openfoam_adapter").string());
  for (const char* a : {"--config"}) prefix.emplace_back(a);
  prefix.push_back(config.string());
  prefix.emplace_back("--output");
  prefix.push_back(output.string());
  return cosim::testing::run(prefix, std::chrono::seconds(300));
}

TEST(OpenFoamAdapterApp, OpenFoamMissingExitsTwoSayingHowToInstallIt) {
  const fs::path dir = fresh_directory("openfoam_adapter_missing");
  write_text(dir / "case.yaml", small_tank);
  const auto r = run_adapter(dir / "case.yaml", dir / "out", {"/usr/bin/env", "PATH=/nonexistent"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("OpenFOAM is not installed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("apt-get install openfoam"), std::string::npos) << r.output;
}

TEST(OpenFoamAdapterApp, AWindowThatIsNotWholeStepsExitsTwoNamingTheKeyAndLine) {
  const fs::path dir = fresh_directory("openfoam_adapter_window");
  std::string text = small_tank;
  text.replace(text.find("window: 0.005"), 13, "window: 0.0055");
  write_text(dir / "case.yaml", text);
  const auto r = run_adapter(dir / "case.yaml", dir / "out");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("case.yaml:15"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("window"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("not a whole number of time steps"), std::string::npos) << r.output;
}

// These run OpenFOAM's own applications. Without Debian's openfoam package
// (a machine set up without .ci/setup) there is nothing to run them on: they
// are skipped with the reason, and main() then exits 77 so that CTest reports
// the executable as not run instead of passed. CI installs OpenFOAM, so there
// they always run.
class OpenFoamAdapterRun : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!openfoam_installed) {
      // Skipped only without OpenFOAM: nothing to run these on (CI installs
      // it, so there they always run); main() then exits 77, "not run".
      GTEST_SKIP() << "OpenFOAM is not installed: " << openfoam::installation_hint();
    }
  }
};

TEST_F(OpenFoamAdapterRun, RunsWindowByWindowAndKeepsOnlyTheLatestTime) {
  const fs::path dir = fresh_directory("openfoam_adapter_tank");
  write_text(dir / "case.yaml", small_tank);
  const auto r = run_adapter(dir / "case.yaml", dir / "out");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Snapshots at 0, 0.01 and 0.02 s.
  for (int step = 0; step < 3; ++step) {
    EXPECT_TRUE(fs::exists(dir / "out" / fmt::format("openfoam_{:06d}.h5", step))) << step;
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "openfoam_000003.h5"));
  const auto times = openfoam::time_directories(dir / "out" / "case");
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[0].name, "0");
  EXPECT_DOUBLE_EQ(times[1].time, 0.02);
  const auto summary = nlohmann::json::parse(read_text(dir / "out" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 0);
  EXPECT_EQ(summary["windows"], 4);
  EXPECT_EQ(summary["steps"], 20);
  const auto& windows = summary["openfoam_windows"];
  ASSERT_EQ(windows["end_time_s"].size(), 4u);
  EXPECT_DOUBLE_EQ(windows["end_time_s"][3].get<double>(), 0.02);
  for (const char* k :
       {"adapter_write_s", "solver_startup_s", "solver_stepping_s", "field_read_s"}) {
    ASSERT_EQ(windows[k].size(), 4u) << k;
    for (const auto& v : windows[k]) EXPECT_GE(v.get<double>(), 0.0) << k;
  }
  // A solver start costs something: the start-up is measured, not zero.
  EXPECT_GT(windows["solver_startup_s"][0].get<double>(), 0.0);
  const auto& water = summary["conserved"]["volume_water"];
  EXPECT_NEAR(water["start"].get<double>(), 0.06 * 0.06, 1e-12);
  EXPECT_LE(std::abs(water["relative_change"].get<double>()), 1e-4);
}

// MPPICInterFoam's restart: started afresh every step, the small tank's dam
// break moves as in one start (restart_inertia.hpp restores the inertia a
// restart loses; without it this tank's water is 19.5 m/s, 15 times its
// speed, off one start's by the 20th); decomposed on two processes it moves
// as on one.
TEST_F(OpenFoamAdapterRun, MppicInterFoamRestartedEveryStepMovesAsInOneStart) {
  const fs::path dir = fresh_directory("openfoam_adapter_mppic_restart");
  std::string text = small_tank;
  text.replace(text.find("generate:"), 0, "solver: MPPICInterFoam\n");
  text.replace(text.find("window: 0.005"), 13, "window: 0.001");
  write_text(dir / "every_step.yaml", text);
  text.replace(text.find("window: 0.001"), 13, "window: 0.02");
  write_text(dir / "one_start.yaml", text);
  // Decomposed, the adapter gathers rho and writes alphac per processor.
  text.replace(text.find("window: 0.02"), 12,
               "window: 0.001\nparallel: {processes: 2, split: [2, 1, 1]}");
  write_text(dir / "two_processes.yaml", text);
  for (const char* run : {"every_step", "one_start", "two_processes"}) {
    const auto r = run_adapter(dir / (std::string(run) + ".yaml"), dir / run);
    ASSERT_EQ(r.exit_code, 0) << run << r.output;
  }
  // U at the end, gathered over the processors by the adapter's own layout.
  const auto velocity = [&](const char* run, int processes) {
    return openfoam::CaseLayout(dir / run / "case", processes, 50).read("0.02", 3).velocity;
  };
  const std::vector<double> every_step = velocity("every_step", 1),
                            one_start = velocity("one_start", 1),
                            two_processes = velocity("two_processes", 2);
  double largest = 0.0, difference = 0.0, parallel = 0.0;
  for (std::size_t i = 0; i < one_start.size(); ++i) {
    largest = std::max(largest, std::abs(one_start[i]));
    difference = std::max(difference, std::abs(every_step[i] - one_start[i]));
    parallel = std::max(parallel, std::abs(two_processes[i] - every_step[i]));
  }
  fmt::print(
      "MPPICInterFoam, 20 starts against 1: largest |dU| {:.3g} m/s of |U| {:.3g} m/s; "
      "on two processes against one: {:.3g} m/s\n",
      difference, largest, parallel);
  EXPECT_GT(largest, 0.1);                // the water is moving
  EXPECT_LE(difference, 2e-5 * largest);  // 4e-6 measured; 15 times |U| without the fix
  EXPECT_LE(parallel, 1e-3 * largest);
}

// The small tank's case made by the adapter in <dir>/made, then copied to
// <dir>/user_case as a user's case with `text` of its `file` replaced by
// `by`; returns <dir>/user.yaml, which runs it.
fs::path users_copy_of_the_made_case(const fs::path& dir, const std::string& file,
                                     const std::string& text, const std::string& by) {
  write_text(dir / "case.yaml", small_tank);
  EXPECT_EQ(run_adapter(dir / "case.yaml", dir / "made").exit_code, 0);
  const fs::path user = dir / "user_case";
  fs::copy(dir / "made" / "case", user, fs::copy_options::recursive);
  fs::remove_all(user / "0.02");
  std::string content = read_text(user / file);
  EXPECT_NE(content.find(text), std::string::npos) << text;
  if (content.find(text) != std::string::npos) content.replace(content.find(text), text.size(), by);
  write_text(user / file, content);
  std::string config = small_tank;
  config.replace(config.find("generate:"), config.find("end_time:") - config.find("generate:"),
                 "directory: user_case\n");
  write_text(dir / "user.yaml", config);
  return dir / "user.yaml";
}

TEST_F(OpenFoamAdapterRun, AFailingOpenFoamRunExitsThreeWithItsLogAndKeepsTheCase) {
  const fs::path dir = fresh_directory("openfoam_adapter_failing");
  // The user's pressure solver is unknown to OpenFOAM.
  const fs::path config = users_copy_of_the_made_case(
      dir, "system/fvSolution", "solver PCG;\n        preconditioner DIC;\n        tolerance 1e-7;",
      "solver XYZ;\n        preconditioner DIC;\n        tolerance 1e-7;");
  const auto r = run_adapter(config, dir / "out");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("OpenFOAM's interFoam"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("XYZ"), std::string::npos) << r.output;  // the log's last lines
  EXPECT_TRUE(fs::exists(dir / "out" / "case" / "system" / "fvSolution"));
  const auto summary = nlohmann::json::parse(read_text(dir / "out" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 3);
}

// A user's case is asked for its fluids by OpenFOAM's own foamDictionary: a
// density left out is bad input naming the file and the entry.
TEST_F(OpenFoamAdapterRun, AUsersCaseWithoutAFluidsDensityExitsTwoNamingFileAndEntry) {
  const fs::path dir = fresh_directory("openfoam_adapter_user_fluids");
  const fs::path config =
      users_copy_of_the_made_case(dir, "constant/transportProperties", "rho 1000;", "");
  const auto r = run_adapter(config, dir / "out");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("constant/transportProperties"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("water/rho"), std::string::npos) << r.output;
}

// The Darcy column of configs/openfoam_coupled/darcy (OpenFOAM's water
// through a held MPM column), four windows, explicit and then implicit with
// no acceleration and a limit only an exact repetition meets: every window
// runs twice, the second time from the start directory kept for it, and must
// reproduce the first bit for bit (its residual 0). Only accepted windows
// leave outputs, so both runs write the same files.
TEST_F(OpenFoamAdapterRun, AWindowRunAgainFromItsStartRepeatsItBitForBit) {
  const fs::path dir = fresh_directory("openfoam_adapter_repeat");
  const fs::path case_dir = fs::path(COSIM_SOURCE_DIR) / "configs" / "openfoam_coupled" / "darcy";
  std::string job = read_text(case_dir / "job.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = job.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    job.replace(at, from.size(), to);
  };
  replace("end_time: 0.08", "end_time: 0.02");
  replace("config: water.yaml", "config: " + (case_dir / "water.yaml").string());
  replace("config: column.yaml", "config: " + (case_dir / "column.yaml").string());
  write_text(dir / "explicit.yaml", job);
  write_text(dir / "implicit.yaml", job + R"(coupling:
  scheme: parallel-implicit
  convergence:
    - {field: column.pore_pressure, absolute: 1.0e-300}
    - {field: water.solid_fraction, absolute: 1.0e-300}
  acceleration: {method: none}
)");
  for (const char* scheme : {"explicit", "implicit"}) {
    const auto r = cosim::testing::run(
        {binary("cosim").string(), "run", (dir / (std::string(scheme) + ".yaml")).string(),
         "--output", (dir / scheme).string()},
        std::chrono::seconds(300));
    ASSERT_EQ(r.exit_code, 0) << scheme << ":\n" << r.output;
  }
  const auto coupling =
      nlohmann::json::parse(read_text(dir / "implicit" / "summary.json"))["coupling"];
  EXPECT_EQ(coupling["windows"], 4);
  EXPECT_EQ(coupling["iterations"], 8);  // each window twice: the second repeats the first
  EXPECT_EQ(coupling["windows_not_converged"], 0);
  const auto water = nlohmann::json::parse(read_text(dir / "implicit" / "water" / "summary.json"));
  EXPECT_EQ(water["metrics"]["state_restores"]["value"], 4.0);

  for (const char* file : {"water/gauges.csv", "water/soil_exchange.csv", "column/probes.csv"}) {
    if (!fs::exists(dir / "explicit" / file)) continue;
    EXPECT_EQ(read_text(dir / "explicit" / file), read_text(dir / "implicit" / file)) << file;
  }
  std::size_t snapshots = 0;
  for (const auto& entry : fs::directory_iterator(dir / "explicit" / "water")) {
    if (entry.path().extension() != ".h5") continue;
    ++snapshots;
    EXPECT_EQ(hdf5_contents(entry.path()),
              hdf5_contents(dir / "implicit" / "water" / entry.path().filename()))
        << entry.path().filename();
  }
  EXPECT_GE(snapshots, 2u);
  // The case keeps the times a plain run keeps: no window's start is left.
  std::vector<std::string> explicit_times, implicit_times;
  for (const auto& [times, scheme] :
       {std::pair{&explicit_times, "explicit"}, std::pair{&implicit_times, "implicit"}})
    for (const auto& entry : fs::directory_iterator(dir / scheme / "water" / "case"))
      times->push_back(entry.path().filename().string());
  std::sort(explicit_times.begin(), explicit_times.end());
  std::sort(implicit_times.begin(), implicit_times.end());
  EXPECT_EQ(explicit_times, implicit_times);
}

// configs/openfoam_coupled/darcy's job to 0.02 s (four windows), its
// participants' configs in the source tree.
std::string darcy_job_of_four_windows() {
  const fs::path case_dir = fs::path(COSIM_SOURCE_DIR) / "configs" / "openfoam_coupled" / "darcy";
  std::string job = read_text(case_dir / "job.yaml");
  job = replaced(job, "end_time: 0.08", "end_time: 0.02");
  job = replaced(job, "config: water.yaml", "config: " + (case_dir / "water.yaml").string());
  return replaced(job, "config: column.yaml", "config: " + (case_dir / "column.yaml").string());
}

// The Darcy pairing (porosity zones) continued from a checkpoint after its
// second window: the case's time directory, the fields and the coupling's
// carried state come back, and what the adapter and the soil write after
// the checkpoint equals the uninterrupted run's bit for bit, explicit and
// implicit.
TEST_F(OpenFoamAdapterRun, ACoupledRunContinuesFromACheckpointBitForBit) {
  const std::string job = darcy_job_of_four_windows();
  const fs::path explicit_dir = fresh_directory("openfoam_checkpoint_explicit");
  write_text(explicit_dir / "job.yaml", job);
  expect_restart_continues(explicit_dir, explicit_dir / "job.yaml", "2", 2);
  const fs::path implicit_dir = fresh_directory("openfoam_checkpoint_implicit");
  write_text(implicit_dir / "job.yaml", job + R"(coupling:
  scheme: parallel-implicit
  convergence:
    - {field: column.pore_pressure, relative: 1.0e-6}
    - {field: water.solid_fraction, relative: 1.0e-6}
)");
  expect_restart_continues(implicit_dir, implicit_dir / "job.yaml", "2", 2);
}

// The water's `ranks: 2` (OpenFOAM on two processes): a checkpoint holds
// the decomposed time directory and continues on two processes bit for bit;
// the same checkpoint with the water on one process (the job's ranks alone
// changed, which a checkpoint otherwise allows) is refused with exit 2.
TEST_F(OpenFoamAdapterRun, ACheckpointOfOpenFoamOnTwoProcessesContinuesOnTwoOnly) {
  const std::string job = darcy_job_of_four_windows();
  const fs::path dir = fresh_directory("openfoam_checkpoint_two_processes");
  write_text(dir / "job.yaml", replaced(job, "executable: openfoam_adapter",
                                        "executable: openfoam_adapter\n    ranks: 2"));
  expect_restart_continues(dir, dir / "job.yaml", "2", 2);
  EXPECT_TRUE(fs::is_directory(checkpoint_of(dir / "whole", 2) / "water" / "time" / "processor1"));
  write_text(dir / "serial.yaml", replaced(job, "executable: openfoam_adapter",
                                           "executable: openfoam_adapter\n    ranks: 1"));
  const auto refused = run_job(dir / "serial.yaml", dir / "serial",
                               {"--restart", checkpoint_of(dir / "whole", 2).string()});
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("decomposed for 2 processes, and this run has OpenFOAM on 1"),
            std::string::npos)
      << refused.output;
}

// Pan et al.'s underwater granular collapse (MPPICInterFoam, the soil as
// parcels), six windows: the restart also brings back the parcels' cloud,
// the fluid fraction and the next start's inertia the end directory holds.
TEST_F(OpenFoamAdapterRun, AParcelCoupledRunContinuesFromACheckpointBitForBit) {
  const fs::path case_dir =
      fs::path(COSIM_SOURCE_DIR) / "configs" / "openfoam_coupled" / "granular_collapse";
  std::string job = read_text(case_dir / "job.yaml");
  job = replaced(job, "end_time: 2.0", "end_time: 6.0e-4");
  job = replaced(job, "config: water.yaml", "config: " + (case_dir / "water.yaml").string());
  job = replaced(job, "config: soil.yaml", "config: " + (case_dir / "soil.yaml").string());
  const fs::path dir = fresh_directory("openfoam_checkpoint_parcels");
  write_text(dir / "job.yaml", job);
  expect_restart_continues(dir, dir / "job.yaml", "3", 3);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    openfoam::find_installation(
        {"interFoam", "MPPICInterFoam", "blockMesh", "setFields", "postProcess"});
    openfoam_installed = true;
  } catch (const cosim::Error& e) {
    fmt::print("OpenFOAM tests not run: {}\n", e.what());
  }
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  return result == 0 && !openfoam_installed ? 77 : result;
}
