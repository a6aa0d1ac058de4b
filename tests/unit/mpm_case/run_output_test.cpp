// The outputs of a run and the run driver's observer protocol, on a tiny
// case (a falling elastic block of 16 particles).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cosim/error.hpp"
#include "mpm/case/load_case.hpp"
#include "mpm/io/particle_snapshot_writer.hpp"
#include "mpm/io/probe_recorder.hpp"
#include "mpm/io/run_driver.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace mpm {
namespace {

namespace fs = std::filesystem;
using cosim::testing::read_text;
using ::testing::HasSubstr;

const char* const falling_block = R"(kind: mpm_case
dimension: 2
grid: {origin: [0, 0], upper: [1, 1], cells: [10, 10]}
time: {end_time: 0.02}
gravity: [0, -10]
materials:
  rubber: {type: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.25}
bodies:
  - name: block
    material: rubber
    geometry: {box: {min: [0.4, 0.4], max: [0.6, 0.6]}}
probes:
  - {name: p, body: block, position: [0.5, 0.5]}
output: {every: 0.01}
threads: 1
)";

TEST(MpmLogarithmicStrain, IsTheLogOfTheStretchAndIgnoresRotation) {
  Tensor F = Tensor::Identity();
  F(0, 0) = 2.0;
  const Tensor e = logarithmic_strain(F);
  EXPECT_NEAR(e(0, 0), std::log(2.0), 1e-14);
  EXPECT_NEAR(e(1, 1), 0.0, 1e-14);
  EXPECT_NEAR(e(0, 1), 0.0, 1e-14);

  const double a = 0.7;
  Tensor R = Tensor::Identity();
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  // Left Hencky strain of R U: R ln(U) R^T.
  const Tensor rotated = logarithmic_strain(R * F);
  const Tensor expected = R * e * R.transpose();
  EXPECT_LE((rotated - expected).norm(), 1e-13) << (rotated - expected).norm();
  EXPECT_LE(logarithmic_strain(R).norm(), 1e-14);
}

TEST(MpmParticleSnapshots, WriteDisplacementFromTheStartAndEveryField) {
  const cosim::testing::ScratchDirectory dir;
  Solver<2> solver(load_case_text(falling_block, dir / "case.yaml"));
  ParticleSnapshotWriter<2> writer(dir.path(), solver);
  writer.write(solver);
  solver.step(1e-3);
  writer.write(solver);
  EXPECT_EQ(writer.snapshots_written(), 2u);
  EXPECT_TRUE(fs::exists(dir / "particles_000001.h5"));
  const std::string xdmf = read_text(dir / "particles.xdmf");
  for (const char* field :
       {"velocity", "displacement", "stress", "effective_stress", "strain", "plastic_strain",
        "porosity", "pore_pressure", "damage", "body", "mass", "volume"})
    EXPECT_THAT(xdmf, HasSubstr(std::string("Name=\"") + field + "\"")) << field;
}

TEST(MpmProbeRecorder, ColumnsCarryUnits) {
  ProbeSpec probe;
  probe.name = "toe";
  const auto columns = ProbeRecorder<2>::columns({probe});
  ASSERT_EQ(columns.size(), 11u);
  EXPECT_EQ(columns[0], "time [s]");
  EXPECT_EQ(columns[1], "toe_displacement_x [m]");
  EXPECT_EQ(columns[4], "toe_velocity_y [m/s]");
  EXPECT_EQ(columns[6], "toe_stress_yy [Pa]");
  EXPECT_EQ(columns[9], "toe_pore_pressure [Pa]");
  EXPECT_EQ(ProbeRecorder<3>::columns({probe}).size(), 1u + 3 + 3 + 6 + 2);
}

// Records what the driver calls; ends the run after `windows` windows of
// `window` seconds, as a coupling would.
struct Calls {
  int initialize = 0;
  int after_step = 0;
  int finalize = 0;
  int abort = 0;
  double largest_dt = 0.0;
  double time = 0.0;
};

class RecordingObserver final : public StepObserver<2> {
 public:
  RecordingObserver(Calls& calls, double window, double end)
      : calls_(calls), window_(window), end_(end) {}
  void initialize(Solver<2>&) override { ++calls_.initialize; }
  double max_time_step() const override {
    const double window_end = window_ * (std::floor(calls_.time / window_ + 1e-9) + 1.0);
    return window_end - calls_.time;
  }
  void after_step(Solver<2>& solver, double dt) override {
    ++calls_.after_step;
    calls_.largest_dt = std::max(calls_.largest_dt, dt);
    calls_.time = solver.time();
    if (failing_ && calls_.after_step == 3) throw cosim::NumericalError("observer failed");
  }
  bool is_ongoing() const override { return calls_.time < end_ - 1e-12; }
  void finalize() override { ++calls_.finalize; }
  void abort(std::string_view) override { ++calls_.abort; }
  nlohmann::json summary(GridPartition<2>*) const override { return {{"windows", 7}}; }
  bool failing_ = false;

 private:
  Calls& calls_;
  double window_;
  double end_;
};

TEST(MpmRunDriver, ObserverDrivesTheLoopAndBoundsTheStep) {
  const cosim::testing::ScratchDirectory dir;
  Calls calls;
  StepObservers observers;
  observers.for_2d = [&calls](const CaseDescription&) {
    return std::make_unique<RecordingObserver>(calls, 1e-3, 0.005);
  };
  RunOptions options;
  options.config = dir.write("case.yaml", falling_block);
  options.output = dir / "out";
  EXPECT_EQ(run_case(options, observers), 0);
  EXPECT_EQ(calls.initialize, 1);
  EXPECT_EQ(calls.finalize, 1);
  EXPECT_EQ(calls.abort, 0);
  EXPECT_GE(calls.after_step, 5);
  EXPECT_LE(calls.largest_dt, 1e-3 + 1e-15);
  EXPECT_NEAR(calls.time, 0.005, 1e-12);  // the observer's end, not the case's 0.02 s
  const auto summary = nlohmann::json::parse(read_text(dir / "out" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 0);
  EXPECT_EQ(summary["coupling"]["windows"], 7);
  EXPECT_EQ(summary["steps"], calls.after_step);
  // A snapshot at the start and one at the (early) end.
  EXPECT_TRUE(fs::exists(dir / "out" / "particles_000001.h5"));
}

TEST(MpmRunDriver, ObserverIsAbortedOnFailure) {
  const cosim::testing::ScratchDirectory dir;
  Calls calls;
  StepObservers observers;
  observers.for_2d = [&calls](const CaseDescription&) {
    auto observer = std::make_unique<RecordingObserver>(calls, 1e-3, 0.005);
    observer->failing_ = true;
    return observer;
  };
  RunOptions options;
  options.config = dir.write("case.yaml", falling_block);
  options.output = dir / "out";
  EXPECT_EQ(run_case(options, observers), 4);
  EXPECT_EQ(calls.abort, 1);
  EXPECT_EQ(calls.finalize, 0);
  const auto summary = nlohmann::json::parse(read_text(dir / "out" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 4);
  EXPECT_EQ(summary["status"]["message"], "observer failed");
}

TEST(MpmRunDriver, StandaloneRunHitsOutputTimesAndEndTime) {
  const cosim::testing::ScratchDirectory dir;
  RunOptions options;
  options.config = dir.write("case.yaml", falling_block);
  options.output = dir / "out";
  ASSERT_EQ(run_case(options), 0);
  // Probes follow the snapshots (probe_every 0): t = 0, 0.01, 0.02 exactly.
  std::ifstream probes(dir / "out" / "probes.csv");
  std::string line;
  std::vector<double> times;
  std::getline(probes, line);
  while (std::getline(probes, line)) times.push_back(std::stod(line.substr(0, line.find(','))));
  ASSERT_EQ(times.size(), 3u);
  EXPECT_DOUBLE_EQ(times[1], 0.01);
  EXPECT_NEAR(times[2], 0.02, 1e-15);
  EXPECT_FALSE(fs::exists(dir / "out" / "particles_000003.h5"));
}

}  // namespace
}  // namespace mpm
