#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <vector>

#include "cosim/error.hpp"
#include "same_bits.hpp"
#include "solver_1d_cases.hpp"

namespace {

using cosim::testing::same_bits;

// The state the solver shows and the steps it takes from it.
struct Trajectory {
  std::vector<double> h, q, bed, steps;

  static Trajectory of(swe::Solver& s, int steps) {
    Trajectory t;
    for (int k = 0; k < steps; ++k) {
      t.steps.push_back(s.stable_time_step());
      s.step(t.steps.back());
    }
    t.h.assign(s.depth().begin(), s.depth().end());
    t.q.assign(s.discharge_x().begin(), s.discharge_x().end());
    t.bed.assign(s.bed().begin(), s.bed().end());
    return t;
  }
};

void expect_same_bits(const Trajectory& a, const Trajectory& b) {
  EXPECT_TRUE(same_bits(a.steps, b.steps));
  EXPECT_TRUE(same_bits(a.h, b.h));
  EXPECT_TRUE(same_bits(a.q, b.q));
  EXPECT_TRUE(same_bits(a.bed, b.bed));
}

// A coupling window run again from the saved state: a dam break over a bumpy
// bed onto dry cells, with friction and an inflow, repeats its steps bit for
// bit, also after the bed changed during the first attempt, and as often as
// the window runs.
TEST(Solver1dSaveRestore, ARestoredSolverRepeatsItsStepsBitForBit) {
  const std::size_t n = 120;
  const auto edges = swe_test::uneven_edges(n, 0.0, 1.0);
  const auto x = swe_test::centres(edges);
  std::vector<double> h(n), bed(n), raised_bed(n);
  for (std::size_t i = 0; i < n; ++i) {
    h[i] = x[i] < 0.3 ? 0.8 : 0.0;
    bed[i] = 0.05 * std::sin(20.0 * x[i]);
    raised_bed[i] = bed[i] + 0.01;
  }
  swe::Physics physics;
  physics.manning = 0.02;
  swe::Solver1d s(edges, physics, {},
                  {{swe::BoundaryKind::inflow_discharge, 0.1}, {swe::BoundaryKind::wall, 0.0}});
  s.set_bed(bed);
  s.set_state(h, std::vector<double>(n, 0.0), {});
  Trajectory::of(s, 20);
  s.save_state();
  const Trajectory saved = Trajectory::of(s, 0);
  const Trajectory first = Trajectory::of(s, 30);
  s.set_bed(raised_bed);
  Trajectory::of(s, 5);
  for (int attempt = 2; attempt <= 3; ++attempt) {
    s.restore_state();
    expect_same_bits(Trajectory::of(s, 0), saved);
    expect_same_bits(Trajectory::of(s, 30), first);
  }
}

// A checkpoint: the state written to a state file and read by a solver
// built afresh (a restarted run) takes the same steps bit for bit; a file of
// another grid is refused.
TEST(Solver1dSaveRestore, AStateFileReadByAFreshSolverContinuesBitForBit) {
  const std::size_t n = 80;
  const auto edges = swe_test::uneven_edges(n, 0.0, 1.0);
  const auto make = [&](std::size_t cells) {
    swe::Physics physics;
    physics.manning = 0.02;
    auto s = std::make_unique<swe::Solver1d>(
        cells == n ? edges : swe_test::uneven_edges(cells, 0.0, 1.0), physics, swe::Scheme{},
        swe::Boundaries1d{{swe::BoundaryKind::inflow_discharge, 0.1},
                          {swe::BoundaryKind::wall, 0.0}});
    std::vector<double> h(cells), bed(cells);
    for (std::size_t i = 0; i < cells; ++i) {
      h[i] = i < cells / 3 ? 0.8 : 0.1;
      bed[i] = 0.05 * std::sin(20.0 * static_cast<double>(i) / static_cast<double>(cells));
    }
    s->set_bed(bed);
    s->set_state(h, std::vector<double>(cells, 0.0), {});
    return s;
  };
  auto first = make(n);
  Trajectory::of(*first, 25);
  const auto file = std::filesystem::path(COSIM_BINARY_DIR) / "test_runs" / "swe_1d_state.h5";
  std::filesystem::create_directories(file.parent_path());
  {
    cosim::StateFileWriter out(file, "swe_1d_test", 1);
    first->write_state(out);
    out.commit();
  }
  auto restarted = make(n);
  restarted->read_state(cosim::StateFileReader(file, "swe_1d_test", 1));
  expect_same_bits(Trajectory::of(*restarted, 0), Trajectory::of(*first, 0));
  expect_same_bits(Trajectory::of(*restarted, 40), Trajectory::of(*first, 40));
  EXPECT_THROW(make(n + 1)->read_state(cosim::StateFileReader(file, "swe_1d_test", 1)),
               cosim::Error);
}

TEST(Solver1dSaveRestore, RefusesToRestoreWhatWasNeverSaved) {
  swe::Solver1d s(swe_test::uniform_edges(4, 0.0, 1.0), {}, {}, swe_test::walls());
  EXPECT_THROW(s.restore_state(), cosim::Error);
}

}  // namespace
