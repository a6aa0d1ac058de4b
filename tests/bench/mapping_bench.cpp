// Mapping operators: apply throughput (values/s) and build time.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "cosim/mapping/build_operator.hpp"

namespace {

using cosim::GridLocation;
using cosim::Mesh;
using cosim::PointCloud;
using cosim::UniformGrid;
using namespace cosim::mapping;

const Mesh& grid_100() {
  static const Mesh m{
      "grid_100",
      UniformGrid{3, {0, 0, 0}, {0.01, 0.01, 0.01}, {100, 100, 100}, GridLocation::cell}};
  return m;
}

const Mesh& grid_90_offset() {
  static const Mesh m{
      "grid_90",
      UniformGrid{
          3, {0.004, -0.003, 0.002}, {0.0111, 0.0111, 0.0111}, {89, 89, 89}, GridLocation::node}};
  return m;
}

// 1e6 particles in the unit cube, 8 per cell of the 50³ MPM grid.
const Mesh& particles_1e6() {
  static const Mesh m = [] {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    PointCloud cloud{3, {}, {}};
    const std::size_t n = 1'000'000;
    cloud.positions.resize(3 * n);
    for (double& x : cloud.positions) x = u(rng);
    cloud.volumes.assign(n, 1.0 / static_cast<double>(n));
    return Mesh{"particles", cloud};
  }();
  return m;
}

const Mesh& mpm_grid() {
  static const Mesh m{
      "mpm_grid", UniformGrid{3, {0, 0, 0}, {0.02, 0.02, 0.02}, {50, 50, 50}, GridLocation::node}};
  return m;
}

void run_apply(benchmark::State& state, const Operator& op) {
  std::vector<double> source(op.source_size(), 1.0);
  std::vector<double> target(op.target_size());
  for (auto _ : state) {
    op.apply(source, target);
    benchmark::DoNotOptimize(target.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(op.source_size()));
  state.counters["weights"] = static_cast<double>(op.weights().nonZeros());
}

void BM_ApplyGridToGridConservative(benchmark::State& state) {
  static const Operator op = build_operator(grid_100(), grid_90_offset(), Constraint::conservative);
  run_apply(state, op);
}
BENCHMARK(BM_ApplyGridToGridConservative)->Unit(benchmark::kMillisecond);

void BM_ApplyGridToGridConsistent(benchmark::State& state) {
  static const Operator op = build_operator(grid_90_offset(), grid_100(), Constraint::consistent);
  run_apply(state, op);
}
BENCHMARK(BM_ApplyGridToGridConsistent)->Unit(benchmark::kMillisecond);

void BM_BuildGridToGrid(benchmark::State& state) {
  for (auto _ : state) {
    Operator op = build_operator(grid_100(), grid_90_offset(), Constraint::conservative);
    benchmark::DoNotOptimize(op.weights().nonZeros());
  }
}
BENCHMARK(BM_BuildGridToGrid)->Unit(benchmark::kMillisecond);

Kernel kernel_of(const benchmark::State& state) {
  return state.range(0) == 0 ? Kernel::linear : Kernel::quadratic_bspline;
}

void BM_ApplyParticlesToGrid(benchmark::State& state) {
  const Operator op =
      build_operator(particles_1e6(), mpm_grid(), Constraint::conservative, {kernel_of(state)});
  state.SetLabel(to_string(kernel_of(state)));
  run_apply(state, op);
}
BENCHMARK(BM_ApplyParticlesToGrid)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_ApplyGridToParticles(benchmark::State& state) {
  const Operator op =
      build_operator(mpm_grid(), particles_1e6(), Constraint::consistent, {kernel_of(state)});
  state.SetLabel(to_string(kernel_of(state)));
  run_apply(state, op);
}
BENCHMARK(BM_ApplyGridToParticles)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_BuildParticlesToGrid(benchmark::State& state) {
  const Constraint constraint =
      state.range(1) == 0 ? Constraint::conservative : Constraint::consistent;
  state.SetLabel(std::string(to_string(kernel_of(state))) + " " + to_string(constraint));
  for (auto _ : state) {
    Operator op = build_operator(particles_1e6(), mpm_grid(), constraint, {kernel_of(state)});
    benchmark::DoNotOptimize(op.weights().nonZeros());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(particles_1e6().size()));
}
BENCHMARK(BM_BuildParticlesToGrid)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
