// MPM solver throughput: particle-updates per second of whole steps (stable
// time step, P2G, grid update, G2P, MUSL re-map, stress update) of a
// Mohr-Coulomb column collapsing under gravity, for each shape kernel, in 2D
// (1e5 and 1e6 points) and 3D (1e6 points), on 1 and 2 OpenMP threads.
// Points are seeded 2 per cell and direction; the column stands in a corner
// of the grid (slip walls, fixed base) with room to spread sideways.
//
// Counters: items_per_second (particle-updates/s), particle_bytes
// (Particles::bytes_per_particle), grid_bytes (grid arrays / points), bytes
// (their sum), yielded (fraction of points with plastic strain). After the
// run a summary gives the median rates on 1 and 2 threads, the rate per
// CPU-second (per busy core) and the 1 -> 2 thread speed-up.
//
// MpmSaveRestore: going back to a coupling window's start (Solver::save then
// Solver::restore, as an implicit window's iteration does) on the 2D GIMP
// column; counters: saved_MB and in_steps (save + restore over the median of
// the steps timed just before, same solver).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "mpm/solver/solver.hpp"
#include "mpm/solver/solver_state.hpp"
#include "mpm_column.hpp"

namespace {

using mpm::ShapeKind;

constexpr int warm_up_steps = 3;

struct Setup {
  int dimension = 2;
  int column_cells = 0;  // column width in cells (2D: height twice that; 3D: a cube)
  ShapeKind shape = ShapeKind::gimp;
  int threads = 1;

  auto key() const { return std::tuple(dimension, column_cells, shape, threads); }
};

template <int Dim>
double grid_bytes(const mpm::Grid<Dim>& g) {
  const auto bytes = [](const auto& v) {
    return static_cast<double>(v.capacity() *
                               sizeof(typename std::decay_t<decltype(v)>::value_type));
  };
  return bytes(g.mass) + bytes(g.momentum) + bytes(g.force) + bytes(g.velocity) +
         bytes(g.velocity_change) + bytes(g.mass_gradient) + bytes(g.remapped_velocity);
}

// One solver alive at a time (a 3D case holds several hundred MB); the
// repetitions of one benchmark reuse it and keep advancing the collapse.
template <int Dim>
mpm::Solver<Dim>& solver_for(const Setup& setup) {
  static std::unique_ptr<mpm::Solver<Dim>> solver;
  static decltype(setup.key()) key{};
  if (!solver || key != setup.key()) {
    solver.reset();
    solver = std::make_unique<mpm::Solver<Dim>>(
        bench::column_case(setup.dimension, setup.column_cells, setup.shape, setup.threads));
    key = setup.key();
    for (int s = 0; s < warm_up_steps; ++s) solver->step(solver->stable_time_step());
  }
  return *solver;
}

template <int Dim>
void run_steps(benchmark::State& state, const Setup& setup) {
  omp_set_num_threads(setup.threads);
  mpm::Solver<Dim>& solver = solver_for<Dim>(setup);
  omp_set_num_threads(setup.threads);
  for (auto _ : state) {
    solver.step(solver.stable_time_step());
    benchmark::ClobberMemory();
  }
  solver.check_state();
  const auto& particles = solver.particles();
  const auto n = static_cast<double>(particles.size());
  std::size_t yielded = 0;
  for (const double e : particles.plastic_strain) yielded += e > 0.0 ? 1 : 0;
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(particles.size()));
  state.counters["particles"] = n;
  state.counters["particle_bytes"] = particles.bytes_per_particle();
  state.counters["grid_bytes"] = grid_bytes(solver.grid()) / n;
  state.counters["bytes"] = particles.bytes_per_particle() + grid_bytes(solver.grid()) / n;
  state.counters["yielded"] = static_cast<double>(yielded) / n;
}

void save_and_restore(benchmark::State& state, const Setup& setup) {
  omp_set_num_threads(setup.threads);
  mpm::Solver<2>& solver = solver_for<2>(setup);
  std::vector<double> step_seconds;
  for (int s = 0; s < 5; ++s) {
    const auto start = std::chrono::steady_clock::now();
    solver.step(solver.stable_time_step());
    step_seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(step_seconds.begin(), step_seconds.begin() + 2, step_seconds.end());
  const double step = step_seconds[2];
  mpm::SolverState<2> saved;
  solver.save(saved);  // the first save allocates
  for (auto _ : state) {
    solver.save(saved);
    solver.restore(saved);
    benchmark::ClobberMemory();
  }
  state.counters["particles"] = static_cast<double>(solver.particles().size());
  state.counters["saved_MB"] = saved.bytes() / 1e6;
  state.counters["in_steps"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * step,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

std::string shape_name(ShapeKind shape) {
  return std::string(mpm::to_string(shape));
}

std::string case_name(const Setup& s) {
  const double w = s.column_cells;
  const double count = s.dimension == 2 ? 8.0 * w * w : 8.0 * w * w * w;
  return "MpmStep/" + std::to_string(s.dimension) + "D/" + (count < 5e5 ? "1e5" : "1e6") + "/" +
         shape_name(s.shape);
}

void register_all() {
  // 2D: 8 w^2 points (w = 112: 100352, w = 354: 1002528); 3D: 8 w^3 (w = 50: 1e6).
  const std::vector<std::pair<int, int>> sizes{{2, 112}, {2, 354}, {3, 50}};
  for (const auto& [dim, wide] : sizes) {
    for (const ShapeKind shape :
         {ShapeKind::linear, ShapeKind::gimp, ShapeKind::quadratic_bspline}) {
      for (const int threads : {1, 2}) {
        const Setup setup{dim, wide, shape, threads};
        const std::string name = case_name(setup) + "/omp:" + std::to_string(threads);
        auto* b = dim == 2
                      ? benchmark::RegisterBenchmark(
                            name.c_str(), [setup](benchmark::State& s) { run_steps<2>(s, setup); })
                      : benchmark::RegisterBenchmark(
                            name.c_str(), [setup](benchmark::State& s) { run_steps<3>(s, setup); });
        b->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();
      }
    }
  }
  for (const int wide : {112, 354}) {
    const Setup setup{2, wide, ShapeKind::gimp, 1};
    const std::string name =
        std::string("MpmSaveRestore/2D/") + (wide < 200 ? "1e5" : "1e6") + "/gimp";
    benchmark::RegisterBenchmark(name.c_str(),
                                 [setup](benchmark::State& s) { save_and_restore(s, setup); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}

// Console output plus a summary of the medians (or the single runs without
// repetitions): rate per core and the 1 -> 2 thread speed-up.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") continue;
      const std::string name = run.run_name.function_name;
      const auto split = name.rfind("/omp:");
      if (split == std::string::npos) continue;
      const int threads = std::stoi(name.substr(split + 5));
      Row& row = rows_[name.substr(0, split)];
      const auto counter = [&](const char* key) {
        const auto it = run.counters.find(key);
        return it == run.counters.end() ? 0.0 : it->second.value;
      };
      const int column = threads == 1 ? 0 : 1;
      row.rate[column] = counter("items_per_second");
      // Updates per second of process CPU time: the rate per busy core,
      // meaningful when other jobs share the machine.
      const double cpu = run.GetAdjustedCPUTime();
      row.cpu_rate[column] = cpu > 0.0 ? row.rate[column] * run.GetAdjustedRealTime() / cpu : 0.0;
      row.particle_bytes = counter("particle_bytes");
      row.grid_bytes = counter("grid_bytes");
      row.yielded = counter("yielded");
    }
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\nparticle-updates per second [M/s] (wall clock; per CPU-second in brackets)\n");
    std::printf("%-32s %18s %18s %9s %10s %7s %8s\n", "case", "1 thread", "2 threads", "speed-up",
                "particle B", "grid B", "yielded");
    for (const auto& [name, row] : rows_) {
      std::printf("%-32s %8.3f [%7.3f] %8.3f [%7.3f] %9.2f %10.0f %7.1f %8.3f\n", name.c_str(),
                  row.rate[0] / 1e6, row.cpu_rate[0] / 1e6, row.rate[1] / 1e6,
                  row.cpu_rate[1] / 1e6, row.rate[0] > 0.0 ? row.rate[1] / row.rate[0] : 0.0,
                  row.particle_bytes, row.grid_bytes, row.yielded);
    }
    std::fflush(stdout);
  }

 private:
  struct Row {
    double rate[2] = {0.0, 0.0};
    double cpu_rate[2] = {0.0, 0.0};
    double particle_bytes = 0.0;
    double grid_bytes = 0.0;
    double yielded = 0.0;
  };
  std::map<std::string, Row> rows_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  register_all();
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
