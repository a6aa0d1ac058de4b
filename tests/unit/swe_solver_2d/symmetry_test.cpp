#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <memory>
#include <vector>

#include "solver_2d_fixture.hpp"
#include "swe/solver_2d.hpp"

namespace {

using swe_2d_test::run_steps;
using swe_2d_test::sample;

double bed_of(double x, double y) {
  return 0.2 * std::exp(-8 * ((x - 0.6) * (x - 0.6) + (y - 0.4) * (y - 0.4))) + 0.05 * x;
}
double depth_of(double x, double y) {
  return std::max(0.0, (x + 0.5 * y < 0.5 ? 0.6 : 0.25) - bed_of(x, y));
}

// The same problem with x and y exchanged: grid, fields, boundaries.
struct Problem {
  swe::Grid2d grid;
  swe::Boundaries2d boundaries;
  bool transposed;

  double bed(double x, double y) const { return transposed ? bed_of(y, x) : bed_of(x, y); }
  double depth(double x, double y) const { return transposed ? depth_of(y, x) : depth_of(x, y); }
  double velocity_x(double x, double y) const {
    return transposed ? 0.3 * std::sin(3 * x) : 0.2 * y;
  }
  double velocity_y(double x, double y) const {
    return transposed ? 0.2 * x : 0.3 * std::sin(3 * y);
  }
};

std::unique_ptr<swe::Solver2d> run(const Problem& p, int steps) {
  swe::Physics physics;
  physics.manning = 0.02;
  auto result = std::make_unique<swe::Solver2d>(p.grid, physics, swe::Scheme{}, p.boundaries);
  swe::Solver2d& solver = *result;
  solver.set_bed(sample(p.grid, [&](double x, double y) { return p.bed(x, y); }));
  const auto h = sample(p.grid, [&](double x, double y) { return p.depth(x, y); });
  const auto hu =
      sample(p.grid, [&](double x, double y) { return p.depth(x, y) * p.velocity_x(x, y); });
  const auto hv =
      sample(p.grid, [&](double x, double y) { return p.depth(x, y) * p.velocity_y(x, y); });
  solver.set_state(h, hu, hv);
  run_steps(solver, steps);
  return result;
}

TEST(Solver2dSymmetry, TransposingTheProblemTransposesTheSolutionBitwise) {
  const int nx = 23, ny = 14;
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0},
      open{swe::BoundaryKind::transmissive, 0.0}, inflow{swe::BoundaryKind::inflow_discharge, 0.05},
      level{swe::BoundaryKind::fixed_depth, 0.3};
  const Problem original{{{0, 0}, {0.05, 0.07}, {nx, ny}}, {wall, open, level, inflow}, false};
  const Problem transposed{{{0, 0}, {0.07, 0.05}, {ny, nx}}, {level, inflow, wall, open}, true};
  const auto pa = run(original, 60), pb = run(transposed, 60);
  const swe::Solver2d &a = *pa, &b = *pb;
  int differences = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const std::size_t ca = i + nx * j, cb = j + ny * i;
      differences += a.depth()[ca] != b.depth()[cb];
      differences += a.discharge_x()[ca] != b.discharge_y()[cb];
      differences += a.discharge_y()[ca] != b.discharge_x()[cb];
    }
  }
  EXPECT_EQ(differences, 0);
  EXPECT_GT(std::abs(a.totals().momentum_y), 1e-3);  // something moved
}

TEST(Solver2dSymmetry, AOneDimensionalProblemAlongXStaysOneDimensional) {
  const int nx = 60, ny = 4;
  const swe::Grid2d grid{{0, 0}, {0.02, 0.05}, {nx, ny}};
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0},
      open{swe::BoundaryKind::transmissive, 0.0};
  swe::Solver2d solver(grid, {}, {}, {open, wall, wall, wall});
  solver.set_bed(
      sample(grid, [](double x, double) { return 0.3 * std::exp(-40 * (x - 0.8) * (x - 0.8)); }));
  solver.set_state(sample(grid, [](double x, double) { return x < 0.5 ? 1.0 : 0.1; }), {}, {});
  run_steps(solver, 150);
  int differences = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const std::size_t c = i + nx * j;
      differences += solver.discharge_y()[c] != 0.0;
      differences += solver.depth()[c] != solver.depth()[i];
      differences += solver.discharge_x()[c] != solver.discharge_x()[i];
    }
  }
  EXPECT_EQ(differences, 0);
  EXPECT_GT(solver.discharge_x()[nx / 2], 0.1);
}

TEST(Solver2dSymmetry, GivesTheSameBitsOnOneAndTwoThreads) {
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0};
  const Problem p{{{0, 0}, {0.01, 0.01}, {110, 90}}, {wall, wall, wall, wall}, false};
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto p1 = run(p, 8);
  omp_set_num_threads(2);
  const auto p2 = run(p, 8);
  omp_set_num_threads(threads);
  const swe::Solver2d &one = *p1, &two = *p2;
  int differences = 0;
  for (std::size_t c = 0; c < one.cell_count(); ++c) {
    differences += one.depth()[c] != two.depth()[c];
    differences += one.discharge_x()[c] != two.discharge_x()[c];
    differences += one.discharge_y()[c] != two.discharge_y()[c];
  }
  EXPECT_EQ(differences, 0);
}

}  // namespace
