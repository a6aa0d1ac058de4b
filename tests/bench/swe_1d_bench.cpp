// Cell-updates per second of swe::Solver1d: one cell advanced one full step
// (both SSP-RK2 stages, second order: van Leer MUSCL + hydrostatic
// reconstruction) on non-uniform cells, a wet dam break kept away from the
// walls' influence for the timed steps. Args: cells, threads, flux.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <vector>

#include "swe/solver_1d.hpp"

namespace {

void BM_Solver1dStep(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const auto flux = static_cast<swe::FluxKind>(state.range(2));
  omp_set_num_threads(threads);
  std::vector<double> edges{0.0};
  for (std::size_t i = 0; i < n; ++i) {
    edges.push_back(edges.back() + 1.0 + 0.3 * std::sin(1e-3 * static_cast<double>(i)));
  }
  swe::Scheme scheme;
  scheme.flux = flux;
  scheme.limiter = swe::LimiterKind::van_leer;
  swe::Solver1d solver(edges, {}, scheme, {{swe::BoundaryKind::wall, 0.0}, {swe::BoundaryKind::wall, 0.0}});
  std::vector<double> h(n), bed(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) / static_cast<double>(n);
    bed[i] = 0.1 * std::sin(40.0 * x);
    h[i] = (x < 0.5 ? 2.0 : 1.0) + 0.2 * std::sin(300.0 * x) - bed[i];
  }
  solver.set_bed(bed);
  solver.set_state(h, std::vector<double>(n, 0.0), {});
  const double dt = solver.stable_time_step();
  for (auto _ : state) {
    solver.step(dt);
    benchmark::DoNotOptimize(solver.depth().data());
  }
  state.SetLabel(swe::to_string(flux));
  state.counters["cell_updates_per_s"] = benchmark::Counter(
      static_cast<double>(n) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  omp_set_num_threads(omp_get_num_procs());
}

void arguments(benchmark::internal::Benchmark* b) {
  for (auto flux : {swe::FluxKind::hllc, swe::FluxKind::roe}) {
    for (std::int64_t n : {100'000, 1'000'000}) {
      for (std::int64_t threads : {1, 2}) b->Args({n, threads, static_cast<std::int64_t>(flux)});
    }
  }
}

}  // namespace

BENCHMARK(BM_Solver1dStep)->Apply(arguments)->ArgNames({"cells", "threads", "flux"})->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
