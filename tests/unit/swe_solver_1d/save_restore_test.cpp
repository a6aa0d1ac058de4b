#include <gtest/gtest.h>

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

TEST(Solver1dSaveRestore, RefusesToRestoreWhatWasNeverSaved) {
  swe::Solver1d s(swe_test::uniform_edges(4, 0.0, 1.0), {}, {}, swe_test::walls());
  EXPECT_THROW(s.restore_state(), cosim::Error);
}

}  // namespace
