// 2D shallow-water solver throughput: cell-updates per second (one cell
// advanced one whole step: stable time step, both SSP-RK2 stages with MUSCL
// van Leer slopes, hydrostatic reconstruction and HLLC fluxes in x and y,
// Manning friction) of a radial dam break over a bumpy bed with a dry corner,
// on 1e5 (316^2) and 1e6 (1000^2) cells, 1 and 2 OpenMP threads.
//
// BM_TwoPhaseStep: the same flow over a solid layer (van den Bout et al.,
// OpenLISEM Hazard, two-phase mode) covering the half x < 0, 0.2 m deep and
// moving at 0.5 m/s across the water, half of it in blocks: each step adds
// the fluid's sources and relaxes the drag between the phases in every cell
// where both are present (Pudasaini's generalised drag, j = 2, with virtual
// mass); the layer is reset with the water.
//
// Counter cell_updates_per_s (rate over wall time). The CPU column is the
// whole process's CPU time (all threads): cells / CPU time is the rate per
// busy core, the figure to read on a loaded machine. The state is reset
// every 200 steps so the flow keeps moving and never fills the dry corner.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "radial_dam_break.hpp"
#include "swe/solver_2d.hpp"
#include "swe/two_phase/two_phase_exchange.hpp"

namespace {

using DamBreak = bench::RadialDamBreak;

DamBreak dam_break(int n) {
  return bench::radial_dam_break(n, n);
}

// The counters of a run, and the thread count put back.
void report(benchmark::State& state, const swe::Solver& solver, int threads, int previous_threads) {
  benchmark::DoNotOptimize(solver.totals());
  state.counters["cell_updates_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(solver.cell_count()),
      benchmark::Counter::kIsRate);
  state.counters["threads"] = threads;
  omp_set_num_threads(previous_threads);
}

void sizes_and_threads(benchmark::internal::Benchmark* b) {
  b->ArgNames({"cells_per_side", "threads"})
      ->Args({316, 1})
      ->Args({316, 2})
      ->Args({1000, 1})
      ->Args({1000, 2})
      ->Unit(benchmark::kMillisecond)
      ->MeasureProcessCPUTime()
      ->UseRealTime();
}

// The dam break's grid between walls, Manning 0.015.
std::unique_ptr<swe::Solver2d> walled_basin(const DamBreak& d) {
  swe::Physics physics;
  physics.manning = 0.015;
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0};
  return std::make_unique<swe::Solver2d>(d.grid, physics, swe::Scheme{},
                                         swe::Boundaries2d{wall, wall, wall, wall});
}

void BM_Solver2dStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const int previous_threads = omp_get_max_threads();
  omp_set_num_threads(threads);
  const DamBreak d = dam_break(n);
  const auto basin = walled_basin(d);
  swe::Solver2d& solver = *basin;
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
  report(state, solver, threads, previous_threads);
}

BENCHMARK(BM_Solver2dStep)->Apply(sizes_and_threads);

void BM_TwoPhaseStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const int previous_threads = omp_get_max_threads();
  omp_set_num_threads(threads);
  const DamBreak d = dam_break(n);
  const auto basin = walled_basin(d);
  swe::Solver2d& solver = *basin;
  const std::size_t cells = d.bed.size();
  swe::SolidLayer layer = swe::empty_solid_layer(cells, 2650.0);
  for (std::size_t c = 0; c < cells; ++c)
    if (c % static_cast<std::size_t>(n) < static_cast<std::size_t>(n / 2)) {
      layer.depth[c] = 0.2;
      layer.density[c] = 2000.0;
      layer.structured_share[c] = 0.5;
      layer.velocity_y[c] = 0.5;
    }
  swe::TwoPhaseExchange exchange(solver, swe::TwoPhaseParameters{}, swe::UniformSources{}, layer,
                                 d.bed);
  auto reset = [&] {
    exchange.set_layer(layer);
    exchange.apply_bed(solver);
    std::vector<double> h(cells);
    for (std::size_t c = 0; c < cells; ++c) h[c] = std::max(0.0, d.depth[c] - layer.depth[c]);
    solver.set_state(h, {}, {});
  };
  reset();
  int steps = 0;
  for (auto _ : state) {
    if (++steps % 200 == 0) {
      state.PauseTiming();
      reset();
      state.ResumeTiming();
    }
    const double dt = solver.stable_time_step();
    solver.step(dt);
    exchange.after_step(solver, dt);
  }
  report(state, solver, threads, previous_threads);
}

BENCHMARK(BM_TwoPhaseStep)->Apply(sizes_and_threads);

}  // namespace

BENCHMARK_MAIN();
