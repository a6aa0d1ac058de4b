// 2D shallow-water solver throughput: cell-updates per second (one cell
// advanced one whole step: stable time step, both SSP-RK2 stages with MUSCL
// van Leer slopes, hydrostatic reconstruction and HLLC fluxes in x and y,
// Manning friction) of a radial dam break over a bumpy bed with a dry corner,
// on 1e5 (316^2) and 1e6 (1000^2) cells, 1 and 2 OpenMP threads.
//
// Counter cell_updates_per_s (rate over wall time). The CPU column is the
// whole process's CPU time (all threads): cells / CPU time is the rate per
// busy core, the figure to read on a loaded machine. The state is reset
// every 200 steps so the flow keeps moving and never fills the dry corner.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "swe/solver_2d.hpp"

namespace {

struct DamBreak {
  swe::Grid2d grid;
  std::vector<double> bed, depth;
};

DamBreak dam_break(int n) {
  DamBreak d;
  d.grid = {{-1.0, -1.0}, {2.0 / n, 2.0 / n}, {n, n}};
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = -1.0 + (i + 0.5) * d.grid.spacing[0],
                   y = -1.0 + (j + 0.5) * d.grid.spacing[1];
      const double bed =
          0.1 * std::sin(4.0 * x) * std::cos(3.0 * y) + (x + y > 1.2 ? 0.8 * (x + y - 1.2) : 0.0);
      const double surface = x * x + y * y < 0.09 ? 1.0 : 0.5;
      d.bed.push_back(bed);
      d.depth.push_back(std::max(0.0, surface - bed));
    }
  }
  return d;
}

void BM_Solver2dStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const int previous_threads = omp_get_max_threads();
  omp_set_num_threads(threads);
  const DamBreak d = dam_break(n);
  swe::Physics physics;
  physics.manning = 0.015;
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0};
  swe::Solver2d solver(d.grid, physics, swe::Scheme{}, {wall, wall, wall, wall});
  solver.set_bed(d.bed);
  solver.set_state(d.depth, {}, {});
  int steps = 0;
  for (auto _ : state) {
    if (++steps % 200 == 0) {
      state.PauseTiming();
      solver.set_state(d.depth, {}, {});
      state.ResumeTiming();
    }
    solver.step(solver.stable_time_step());
  }
  benchmark::DoNotOptimize(solver.totals());
  state.counters["cell_updates_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(solver.cell_count()),
      benchmark::Counter::kIsRate);
  state.counters["threads"] = threads;
  omp_set_num_threads(previous_threads);
}

BENCHMARK(BM_Solver2dStep)
    ->ArgNames({"cells_per_side", "threads"})
    ->Args({316, 1})
    ->Args({316, 2})
    ->Args({1000, 1})
    ->Args({1000, 2})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
