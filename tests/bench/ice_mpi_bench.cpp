// The ICE solver decomposed over MPI ranks (issue 27), its pressure solved by
// PETSc (CG with BoomerAMG, or the preconditioner named as its argument): strong scaling (the same
// 1000 x 1000 cells on every rank count) and weak scaling (1000 x 500 cells per rank), a water
// column collapsing in air (Martin & Moyce's geometry, water and air, viscous). Run it under mpirun
// on 1, then 2 ranks (`bench` does both), one thread per rank; the efficiencies are the ratios of
// the lines. On one rank the built-in solver (multigrid-preconditioned CG) is timed too.
//
// Per case: the median over 3 repetitions of 4 steps of 2e-5 s from the
// same state (save_state / restore_state); the wall time is the slowest
// rank's. Also per step: the CG iterations, the halo's volume a rank sends,
// and the time a rank spends exchanging ghosts and reducing (waiting for a
// slower neighbour included), the largest over the ranks. The PETSc solve
// itself communicates too; its share is inside ms/step.
#include <fmt/format.h>
#include <mpi.h>

#include <cstdio>
#include <string>
#include <vector>

#include "ice/case/load_case.hpp"
#include "ice/case/make_solver.hpp"
#include "ice/parallel/mpi_block_link.hpp"
#include "ice/solver/saved_state.hpp"
#include "mpi_bench_support.hpp"

namespace {

constexpr int repetitions = 3;
constexpr int steps = 4;
constexpr double dt = 2e-5;

std::string dam_break(int nx, int ny) {
  return fmt::format(R"(kind: ice_case
name: dam_break
dimension: 2
grid: {{origin: [0.0, 0.0], upper: [0.28575, {}], cells: [{}, {}]}}
gravity: [0.0, -9.81]
end_time: 1.0
materials:
  water:
    eos: {{type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8}}
    viscosity: 1.0e-3
  air:
    eos: {{type: ideal_gas, gas_constant: 287.0, heat_capacity_ratio: 1.4}}
    viscosity: 1.8e-5
exchange:
  - {{materials: [water, air], momentum: 1.0e15}}
initial:
  fill: air
  pressure: hydrostatic
  temperature: 293.15
  regions:
    - {{box: {{lower: [0.0, 0.0], upper: [0.1, {}]}}, fill: water}}
boundaries:
  y_max: {{type: fixed_pressure, pressure: 101325}}
)",
                     0.28575 * ny / nx, nx, ny, 0.8 * 0.28575 * ny / nx);
}

struct Timing {
  double step = 0.0, communication = 0.0, iterations = 0.0, values = 0.0;
};

template <class Solver, class Communication>
Timing time_steps(Solver& solver, Communication communication) {
  ice::SavedIceState<2> start;
  solver.save_state(start);
  std::vector<double> wall, comm;
  Timing t;
  for (int r = 0; r < repetitions; ++r) {
    solver.restore_state(start);
    const auto [seconds_before, values_before] = communication();
    MPI_Barrier(MPI_COMM_WORLD);
    const double begin = MPI_Wtime();
    int iterations = 0;
    for (int s = 0; s < steps; ++s) iterations += solver.advance(dt).pressure_iterations;
    const double elapsed = MPI_Wtime() - begin;
    const auto [seconds_after, values_after] = communication();
    wall.push_back(bench::max_over_ranks(elapsed) / steps);
    comm.push_back(bench::max_over_ranks(seconds_after - seconds_before) / steps);
    t.iterations = static_cast<double>(iterations) / steps;
    t.values = bench::max_over_ranks(static_cast<double>(values_after - values_before) / steps);
  }
  t.step = bench::median(wall);
  t.communication = bench::median(comm);
  return t;
}

void print(const char* scaling, const char* pressure, int ranks, double cells, const Timing& t) {
  std::printf("%-6s %-8s %5d %9.0f %9.0f %10.1f %12.3f %8.1f %10.1f %10.1f\n", scaling, pressure,
              ranks, cells, cells / ranks, 1e3 * t.step, cells / t.step / 1e6, t.iterations,
              1e3 * t.communication, 8.0 * t.values / 1024.0);
}

void run_case(const char* scaling, int nx, int ny, const std::string& preconditioner) {
  int ranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const ice::CaseDescription c = ice::load_case_text(dam_break(nx, ny), "dam_break.yaml");
  const double cells = static_cast<double>(nx) * ny;
  if (ranks == 1) {
    auto whole = ice::make_solver<2>(c);
    const Timing t = time_steps(*whole, [] { return std::pair<double, std::size_t>{0.0, 0}; });
    print(scaling, "builtin", 1, cells, t);
  }
  ice::parallel::PetscPressureOptions pressure;
  pressure.tolerance = c.numerics.pressure.tolerance;
  pressure.preconditioner = preconditioner;
  ice::parallel::BlockSolver<2> part =
      ice::parallel::make_block_solver<2>(MPI_COMM_WORLD, c, pressure);
  const auto& link = *part.link;
  const Timing t = time_steps(*part.solver, [&link] {
    return std::pair<double, std::size_t>{link.communication_seconds(), link.values_sent()};
  });
  if (rank == 0) print(scaling, "petsc", ranks, cells, t);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  {
    const ice::parallel::PetscLibrary petsc;
    int rank = 0, ranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (rank == 0) {
      std::printf("ice_mpi_bench: %d ranks, one thread each\n", ranks);
      std::printf("%-6s %-8s %5s %9s %9s %10s %12s %8s %10s %10s\n", "case", "pressure", "ranks",
                  "cells", "per_rank", "ms/step", "M_cell_upd/s", "CG_it", "comm_ms", "halo_KiB");
    }
    const std::string preconditioner = argc > 1 ? argv[1] : "boomeramg";
    if (rank == 0) std::printf("PETSc: CG with %s\n", preconditioner.c_str());
    run_case("strong", 1000, 1000, preconditioner);
    run_case("weak", 1000, 500 * ranks, preconditioner);
  }
  MPI_Finalize();
  return 0;
}
