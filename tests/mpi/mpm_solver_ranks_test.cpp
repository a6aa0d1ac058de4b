// mpm_solver standalone under `mpirun -np N` (label mpi): a sand column
// collapsing (GIMP, MUSL, Mohr-Coulomb), on 1 process and on 2, 3 and 4
// ranks whose cuts move to balance the points, must write the same particle
// snapshots bit for bit (every dataset and attribute, written together by
// the ranks), the same XDMF index and probes.csv (each probe's point sampled
// by the rank holding it), the same steps, and the totals of one process to round-off (the ranks
// sum them in another order); cases a decomposed run cannot take, and an output directory already
// in use, are refused with exit 2, nothing lost.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hdf5_contents.hpp"
#include "launched_program.hpp"
#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

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
output: {every: 0.02, probe_every: 0.005}
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
    for (const char* file : {"particles.xdmf", "probes.csv"})
      EXPECT_EQ(read_text(out / file), read_text(dir / "one_process" / file))
          << file << " on " << ranks << " ranks";
    for (std::size_t s = 0; s < snapshots; ++s) {
      const std::string file = "particles_00000" + std::to_string(s) + ".h5";
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

TEST(MpmSolverRanks, RefusesWhatADecomposedRunCannotTake) {
  expect_refused(replaced(column_case, "safety_factor: 0.4}", "safety_factor: 0.4, window: 0.01}"),
                 "time.window", 2);
  expect_refused(replaced(column_case, "probe_every: 0.005}", "probe_every: 0.005, grid: true}"),
                 "output.grid", 2);
  expect_refused(replaced(column_case, "    cohesion: 0\n",
                          "    cohesion: 0\n    specific_heat: 800\n    thermal_conductivity: 2\n"),
                 "thermal", 2);
  // 25 rows make 7 slabs of 4 rows: not enough for 8 ranks.
  expect_refused(column_case, "grid.cells", 8);
}

TEST(MpmSolverRanks, LeavesAnOutputDirectoryInUseAsItWas) {
  expect_directory_in_use_kept("mpm_solver", column_case);
}

}  // namespace
}  // namespace cosim::testing
