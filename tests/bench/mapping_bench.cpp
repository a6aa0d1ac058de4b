// Mapping operators: apply throughput (values/s) and build time.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "mapping/build_operator.hpp"

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

// 1e6 particles in the unit cube, 8 per cell of the 50³ MPM grid, in random
// order or sorted by cell (as MPM codes that seed cell by cell hold them).
Mesh make_particles(bool sorted_by_cell) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t n = 1'000'000;
  std::vector<std::array<double, 3>> points(n);
  for (auto& x : points) x = {u(rng), u(rng), u(rng)};
  if (sorted_by_cell) {
    const auto cell = [](const std::array<double, 3>& x) {
      const auto c = [](double v) { return static_cast<int>(v * 50.0); };
      return (c(x[2]) * 50 + c(x[1])) * 50 + c(x[0]);
    };
    std::sort(points.begin(), points.end(),
              [&](const auto& a, const auto& b) { return cell(a) < cell(b); });
  }
  PointCloud cloud{3, {}, {}};
  for (const auto& x : points) cloud.positions.insert(cloud.positions.end(), x.begin(), x.end());
  cloud.volumes.assign(n, 1.0 / static_cast<double>(n));
  return Mesh{"particles", cloud};
}

const Mesh& particles_1e6(bool sorted_by_cell = false) {
  static const Mesh random = make_particles(false);
  static const Mesh sorted = make_particles(true);
  return sorted_by_cell ? sorted : random;
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

// args: kernel (0 linear, 1 quadratic B-spline), constraint (0 conservative,
// 1 consistent), particle order (0 random, 1 sorted by cell)
void BM_BuildParticlesToGrid(benchmark::State& state) {
  const Constraint constraint =
      state.range(1) == 0 ? Constraint::conservative : Constraint::consistent;
  const bool sorted = state.range(2) == 1;
  state.SetLabel(std::string(to_string(kernel_of(state))) + " " + to_string(constraint) +
                 (sorted ? " sorted" : " random"));
  const Mesh& particles = particles_1e6(sorted);
  for (auto _ : state) {
    Operator op = build_operator(particles, mpm_grid(), constraint, {kernel_of(state)});
    benchmark::DoNotOptimize(op.weights().nonZeros());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(particles.size()));
}
BENCHMARK(BM_BuildParticlesToGrid)
    ->ArgsProduct({{0, 1}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

void BM_ApplyParticlesToGridSorted(benchmark::State& state) {
  const Operator op =
      build_operator(particles_1e6(true), mpm_grid(), Constraint::conservative, {kernel_of(state)});
  state.SetLabel(to_string(kernel_of(state)));
  run_apply(state, op);
}
BENCHMARK(BM_ApplyParticlesToGridSorted)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
