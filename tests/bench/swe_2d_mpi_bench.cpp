// The 2D shallow-water solver decomposed over MPI ranks (issue 27): strong
// scaling (the same 1000 x 1000 cells on every rank count) and weak scaling
// (1000 x 500 cells per rank), the radial dam break of swe_2d_bench between
// walls. Run it under mpirun on 1, then 2 ranks (`bench` does both), one
// OpenMP thread per rank; the efficiencies are the ratios of the lines.
//
// Per case: the median over 5 repetitions of 40 whole steps (stable time step
// reduced over the ranks, both SSP-RK2 stages, two halo exchanges) from the
// same state; the wall time is the slowest rank's. Also per step: the halo's
// volume a rank sends, and the time a rank spends exchanging and reducing
// (waiting for a slower neighbour included), the largest over the ranks.
#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "mpi_bench_support.hpp"
#include "radial_dam_break.hpp"
#include "swe/parallel/mpi_subdomain_link.hpp"

namespace {

constexpr int repetitions = 5;
constexpr int steps = 40;

void run_case(const char* scaling, int nx, int ny) {
  int ranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const bench::RadialDamBreak whole = bench::radial_dam_break(nx, ny, 0, 0, 0, 0);
  swe::Physics physics;
  physics.manning = 0.015;
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0};
  swe::parallel::BlockSolver2d part = swe::parallel::make_block_solver(
      MPI_COMM_WORLD, whole.grid, physics, swe::Scheme{}, {wall, wall, wall, wall});
  const auto& b = part.block;
  const bench::RadialDamBreak block = bench::radial_dam_break(
      nx, ny, static_cast<int>(b.cells[0].begin), static_cast<int>(b.cells[0].end),
      static_cast<int>(b.cells[1].begin), static_cast<int>(b.cells[1].end));
  swe::Solver2d& solver = *part.solver;
  solver.set_bed(block.bed);
  std::vector<double> wall_per_step, communication_per_step;
  std::size_t values_per_step = 0;
  for (int r = 0; r < repetitions; ++r) {
    solver.set_state(block.depth, {}, {});
    const double communication_before = part.link->communication_seconds();
    const std::size_t values_before = part.link->values_sent();
    MPI_Barrier(MPI_COMM_WORLD);
    const double start = MPI_Wtime();
    for (int s = 0; s < steps; ++s) solver.step(solver.stable_time_step());
    const double elapsed = MPI_Wtime() - start;
    wall_per_step.push_back(bench::max_over_ranks(elapsed) / steps);
    communication_per_step.push_back(
        bench::max_over_ranks(part.link->communication_seconds() - communication_before) / steps);
    values_per_step = (part.link->values_sent() - values_before) / steps;
  }
  const double sent = bench::max_over_ranks(static_cast<double>(values_per_step));
  const double cells = static_cast<double>(nx) * ny;
  const double step = bench::median(wall_per_step);
  if (rank == 0)
    std::printf("%-6s %5d %9.0f %9.0f %10.3f %12.2f %10.3f %10.1f\n", scaling, ranks, cells,
                cells / ranks, 1e3 * step, cells / step / 1e6,
                1e3 * bench::median(communication_per_step), 8.0 * sent / 1024.0);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (rank == 0) {
    std::printf("swe_2d_mpi_bench: %d ranks x %d OpenMP threads\n", ranks, omp_get_max_threads());
    std::printf("%-6s %5s %9s %9s %10s %12s %10s %10s\n", "case", "ranks", "cells", "per_rank",
                "ms/step", "M_cell_upd/s", "comm_ms", "halo_KiB");
  }
  run_case("strong", 1000, 1000);
  run_case("weak", 1000, 500 * ranks);
  MPI_Finalize();
  return 0;
}
