// The MPM solver decomposed over MPI ranks (issue 27): strong scaling (the
// same 2D GIMP column of 1e6 points on every rank count) and weak scaling
// (5e5 points per rank), the collapsing Mohr-Coulomb column of mpm_bench.
// Run it under mpirun on 1, then 2 ranks (`bench` does both), one OpenMP
// thread per rank; the efficiencies are the ratios of the lines.
//
// Per case: the median over 5 repetitions of 10 whole steps (stable time
// step reduced over the ranks, P2G with the ghost sums accumulated, grid
// update, velocities exchanged, G2P, MUSL re-map, migration), each
// repetition from the same saved state; the wall time is the slowest
// rank's. Also per step: the grid values and points a rank sends, the time
// it spends communicating (waiting for a slower neighbour included), the
// largest over the ranks, and the imbalance of the cuts (points of the
// fullest rank over the mean).
#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "mpi_bench_support.hpp"
#include "mpm/parallel/mpi_grid_partition.hpp"
#include "mpm/solver/solver.hpp"
#include "mpm/solver/solver_state.hpp"
#include "mpm_column.hpp"

namespace {

constexpr int repetitions = 5;
constexpr int steps = 10;

// 8 wide^2 points in 2D (2 x 2 per cell of a column 2 wide high).
void run_case(const char* scaling, int wide) {
  int ranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const mpm::CaseDescription c = bench::column_case(2, wide, mpm::ShapeKind::gimp, 1);
  const auto cuts = mpm::parallel::balanced_row_cuts(c, ranks);
  auto partition = std::make_shared<mpm::parallel::MpiGridPartition<2>>(
      MPI_COMM_WORLD, cuts, c.grid.origin[1], c.grid.spacing[1]);
  mpm::Solver<2> solver(c, partition);
  for (int s = 0; s < 3; ++s) solver.step(solver.stable_time_step());
  mpm::SolverState<2> start;
  solver.save(start);
  std::vector<double> wall_per_step, communication_per_step;
  double values_per_step = 0.0, points_per_step = 0.0;
  for (int r = 0; r < repetitions; ++r) {
    solver.restore(start);
    const double communication_before = partition->communication_seconds();
    const auto values_before = static_cast<double>(partition->values_sent());
    const auto points_before = static_cast<double>(partition->points_sent());
    MPI_Barrier(MPI_COMM_WORLD);
    const double begin = MPI_Wtime();
    for (int s = 0; s < steps; ++s) solver.step(solver.stable_time_step());
    const double wall = MPI_Wtime() - begin;
    const double values = static_cast<double>(partition->values_sent()) - values_before;
    const double points = static_cast<double>(partition->points_sent()) - points_before;
    wall_per_step.push_back(bench::max_over_ranks(wall) / steps);
    communication_per_step.push_back(
        bench::max_over_ranks(partition->communication_seconds() - communication_before) / steps);
    values_per_step = values / steps;
    points_per_step = points / steps;
  }
  unsigned long total = solver.particles().size();
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_UNSIGNED_LONG, MPI_SUM, MPI_COMM_WORLD);
  const double values_max = bench::max_over_ranks(values_per_step);
  const double points_max = bench::max_over_ranks(points_per_step);
  if (rank != 0) return;
  const double ms = 1e3 * bench::median(wall_per_step);
  std::printf(
      "%-6s %d rank(s) x 1 thread  %8lu points  %8.1f ms/step  %6.2f M particle-updates/s  "
      "comm %6.2f ms/step  %7.0f grid values and %5.0f points sent/rank/step  imbalance "
      "%.3f\n",
      scaling, ranks, total, ms, static_cast<double>(total) / (ms * 1e-3) / 1e6,
      1e3 * bench::median(communication_per_step), values_max, points_max,
      mpm::parallel::row_imbalance(c, cuts));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  omp_set_num_threads(1);
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  run_case("strong", 354);  // 1.0e6 points whatever the ranks
  run_case("weak", static_cast<int>(std::lround(250.0 * std::sqrt(ranks))));  // 5e5 per rank
  MPI_Finalize();
  return 0;
}
