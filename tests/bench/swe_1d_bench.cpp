// Cell-updates per second of swe::Solver1d: one cell advanced one full step
// (both SSP-RK2 stages, second order: van Leer MUSCL + hydrostatic
// reconstruction) on non-uniform cells, a wet dam break kept away from the
// walls' influence for the timed steps. Args: cells, threads, flux. Also the
// stable time step's scan of the faces.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <memory>
#include <vector>

#include "swe/solver_1d.hpp"

namespace {

// The dam break of both benchmarks: 2 m | 1 m of water over a wavy bed, at rest.
std::unique_ptr<swe::Solver1d> make_dam_break(std::size_t n, swe::FluxKind flux) {
  std::vector<double> edges{0.0};
  for (std::size_t i = 0; i < n; ++i) {
    edges.push_back(edges.back() + 1.0 + 0.3 * std::sin(1e-3 * static_cast<double>(i)));
  }
  swe::Scheme scheme;
  scheme.flux = flux;
  scheme.limiter = swe::LimiterKind::van_leer;
  auto solver = std::make_unique<swe::Solver1d>(
      edges, swe::Physics{}, scheme,
      swe::Boundaries1d{{swe::BoundaryKind::wall, 0.0}, {swe::BoundaryKind::wall, 0.0}});
  std::vector<double> h(n), bed(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) / static_cast<double>(n);
    bed[i] = 0.1 * std::sin(40.0 * x);
    h[i] = (x < 0.5 ? 2.0 : 1.0) + 0.2 * std::sin(300.0 * x) - bed[i];
  }
  solver->set_bed(bed);
  solver->set_state(h, std::vector<double>(n, 0.0), {});
  return solver;
}

void BM_Solver1dStep(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const auto flux = static_cast<swe::FluxKind>(state.range(2));
  omp_set_num_threads(threads);
  const std::unique_ptr<swe::Solver1d> solver = make_dam_break(n, flux);
  const double dt = solver->stable_time_step();
  for (auto _ : state) {
    solver->step(dt);
    benchmark::DoNotOptimize(solver->depth().data());
  }
  state.SetLabel(swe::to_string(flux));
  state.counters["cell_updates_per_s"] =
      benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
  omp_set_num_threads(omp_get_num_procs());
}

// The CFL step (Zheng et al., eq. 37) a coupled run asks for before every
// step: cells scanned per second.
void BM_Solver1dStableTimeStep(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const std::unique_ptr<swe::Solver1d> solver = make_dam_break(n, swe::FluxKind::hllc);
  solver->step(solver->stable_time_step());  // some velocity
  for (auto _ : state) benchmark::DoNotOptimize(solver->stable_time_step());
  state.counters["cells_per_s"] =
      benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
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

BENCHMARK(BM_Solver1dStep)
    ->Apply(arguments)
    ->ArgNames({"cells", "threads", "flux"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Solver1dStableTimeStep)
    ->ArgsProduct({{100'000, 1'000'000}, {1, 2}})
    ->ArgNames({"cells", "threads"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
