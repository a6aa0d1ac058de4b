#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "cosim/error.hpp"
#include "same_bits.hpp"
#include "solver_2d_fixture.hpp"
#include "swe/solver_2d.hpp"

namespace {

using cosim::testing::same_bits;

using swe_2d_test::all_sides;
using swe_2d_test::sample;

// The state the solver shows and the steps it takes from it.
struct Trajectory {
  std::vector<double> h, hu, hv, bed, steps;

  static Trajectory of(swe::Solver& s, int steps) {
    Trajectory t;
    for (int k = 0; k < steps; ++k) {
      t.steps.push_back(s.stable_time_step());
      s.step(t.steps.back());
    }
    t.h.assign(s.depth().begin(), s.depth().end());
    t.hu.assign(s.discharge_x().begin(), s.discharge_x().end());
    t.hv.assign(s.discharge_y().begin(), s.discharge_y().end());
    t.bed.assign(s.bed().begin(), s.bed().end());
    return t;
  }
};

void expect_same_bits(const Trajectory& a, const Trajectory& b) {
  EXPECT_TRUE(same_bits(a.steps, b.steps));
  EXPECT_TRUE(same_bits(a.h, b.h));
  EXPECT_TRUE(same_bits(a.hu, b.hu));
  EXPECT_TRUE(same_bits(a.hv, b.hv));
  EXPECT_TRUE(same_bits(a.bed, b.bed));
}

// A coupling window run again from the saved state: a dam break over a bumpy
// bed onto dry cells, with friction, on enough cells for several threads,
// repeats its steps bit for bit, also after the bed changed during the first
// attempt, and as often as the window runs.
TEST(Solver2dSaveRestore, ARestoredSolverRepeatsItsStepsBitForBit) {
  const swe::Grid2d grid{{0, 0}, {0.01, 0.01}, {100, 100}};
  swe::Physics physics;
  physics.manning = 0.02;
  swe::Solver2d s(grid, physics, {}, all_sides(swe::BoundaryKind::wall));
  const auto bed = sample(grid, [](double x, double y) { return 0.03 * std::sin(9.0 * x * y); });
  auto raised_bed = bed;
  for (double& b : raised_bed) b += 0.01;
  s.set_bed(bed);
  s.set_state(sample(grid, [](double x, double y) { return x < 0.4 && y < 0.5 ? 0.6 : 0.0; }), {},
              {});
  Trajectory::of(s, 10);
  s.save_state();
  const Trajectory saved = Trajectory::of(s, 0);
  const Trajectory first = Trajectory::of(s, 20);
  s.set_bed(raised_bed);
  Trajectory::of(s, 5);
  for (int attempt = 2; attempt <= 3; ++attempt) {
    s.restore_state();
    expect_same_bits(Trajectory::of(s, 0), saved);
    expect_same_bits(Trajectory::of(s, 20), first);
  }
}

// A checkpoint: the state written to a state file and read by a solver
// built afresh (a restarted run) takes the same steps bit for bit.
TEST(Solver2dSaveRestore, AStateFileReadByAFreshSolverContinuesBitForBit) {
  const swe::Grid2d grid{{0, 0}, {0.02, 0.02}, {40, 30}};
  swe::Physics physics;
  physics.manning = 0.02;
  const auto make = [&] {
    auto s = std::make_unique<swe::Solver2d>(grid, physics, swe::Scheme{},
                                             all_sides(swe::BoundaryKind::wall));
    s->set_bed(sample(grid, [](double x, double y) { return 0.02 * std::sin(7.0 * x * y); }));
    s->set_state(sample(grid, [](double x, double) { return x < 0.3 ? 0.5 : 0.05; }), {}, {});
    return s;
  };
  auto first = make();
  Trajectory::of(*first, 15);
  const auto file = std::filesystem::path(COSIM_BINARY_DIR) / "test_runs" / "swe_2d_state.h5";
  std::filesystem::create_directories(file.parent_path());
  {
    cosim::StateFileWriter out(file, "swe_2d_test", 1);
    first->write_state(out);
    out.commit();
  }
  auto restarted = make();
  restarted->read_state(cosim::StateFileReader(file, "swe_2d_test", 1));
  expect_same_bits(Trajectory::of(*restarted, 0), Trajectory::of(*first, 0));
  expect_same_bits(Trajectory::of(*restarted, 25), Trajectory::of(*first, 25));
}

TEST(Solver2dSaveRestore, RefusesToRestoreWhatWasNeverSaved) {
  swe::Solver2d s({{0, 0}, {1.0, 1.0}, {3, 3}}, {}, {}, all_sides(swe::BoundaryKind::wall));
  EXPECT_THROW(s.restore_state(), cosim::Error);
}

}  // namespace
