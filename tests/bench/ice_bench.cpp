// ICE solver throughput: cell-updates per second of the whole step
// (equilibration, face velocities with water-air exchange, implicit
// pressure by preconditioned CG (preconditioner 0 Jacobi, 1 incomplete
// Cholesky, 2 multigrid), Lagrangian phase, van Leer
// advection) for two materials in 2D: a water column collapsing in air
// (Martin & Moyce's geometry, K = 1e15), on 1e5 (316^2) and 1e6 (1000^2)
// cells, one thread. Also reports the CG iterations per step. The state is
// reset every 100 steps so the flow stays in its early, fast phase.
//
// BM_IceSaveRestore2d: going back to a coupling window's start (save_state
// then restore_state, as an implicit window's iteration does) on the same
// dam break; in_steps is its cost over the median of 5 steps timed just
// before on the same solver.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

#include "ice/eos/ideal_gas.hpp"
#include "ice/eos/linear_water.hpp"
#include "ice/solver/ice_solver.hpp"
#include "ice/solver/initial_state.hpp"
#include "ice/solver/saved_state.hpp"

namespace {

struct DamBreak {
  ice::CellGrid<2> grid;
  std::vector<ice::FluidMaterial> materials;
  ice::FluidState<2> state;
};

DamBreak dam_break(int n) {
  const double length = 0.4;
  ice::CellGrid<2> grid(ice::CellGrid<2>::Point(0.0, 0.0),
                        ice::CellGrid<2>::Point(length / n, length / n), {n, n});
  std::vector<ice::FluidMaterial> materials{
      {"water", std::make_shared<ice::LinearWater>(ice::LinearWaterParameters{}), 0.0, 0.0},
      {"air", std::make_shared<ice::IdealGas>(287.0, 717.5), 0.0, 0.0}};
  const auto cells = static_cast<std::size_t>(grid.cell_count());
  ice::CellFill<2> fill;
  fill.material.resize(cells);
  fill.temperature.assign(cells, 293.15);
  for (auto& u : fill.velocity) u.assign(cells, 0.0);
  for (int c = 0; c < grid.cell_count(); ++c) {
    const auto x = grid.cell_centre(c);
    fill.material[static_cast<std::size_t>(c)] = x[0] < 0.1 && x[1] < 0.2 ? 0 : 1;
  }
  const Eigen::Vector2d gravity(0.0, -9.81);
  fill.pressure = ice::hydrostatic_pressure(grid, materials, fill.material, fill.temperature,
                                            gravity, 101325.0, 1e-6);
  ice::FluidState<2> state = ice::make_initial_state(grid, materials, fill, 1e-6);
  return {grid, materials, state};
}

void BM_IceStep2d(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const DamBreak d = dam_break(n);
  ice::ExchangeCoefficients exchange = ice::ExchangeCoefficients::none(2);
  exchange.set(0, 1, 1.0e15, 0.0);
  ice::IceSolver<2>::Sides sides{};
  ice::IceSolverOptions options;
  options.pressure.preconditioner = static_cast<ice::PressurePreconditioner>(state.range(1));
  options.pressure.max_iterations = 20000;  // Jacobi needs > 2000 at 1000^2
  auto solver = std::make_unique<ice::IceSolver<2>>(d.grid, d.materials, exchange, sides,
                                                    Eigen::Vector2d(0.0, -9.81), d.state, options);
  const double dt = 0.4 * d.grid.spacing()[0] / 1.5;  // ~ the collapse's fastest 1.5 m/s
  long steps = 0;
  long iterations = 0;
  for (auto _ : state) {
    if (++steps % 100 == 0) {
      state.PauseTiming();
      solver = std::make_unique<ice::IceSolver<2>>(d.grid, d.materials, exchange, sides,
                                                   Eigen::Vector2d(0.0, -9.81), d.state, options);
      state.ResumeTiming();
    }
    iterations += solver->advance(dt).pressure_iterations;
  }
  state.counters["cell_updates_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(d.grid.cell_count()),
      benchmark::Counter::kIsRate);
  state.counters["cg_iterations_per_step"] =
      static_cast<double>(iterations) / static_cast<double>(state.iterations());
}

BENCHMARK(BM_IceStep2d)
    ->ArgNames({"cells_per_side", "preconditioner"})
    ->ArgsProduct({{316, 1000},
                   {static_cast<long>(ice::PressurePreconditioner::jacobi),
                    static_cast<long>(ice::PressurePreconditioner::incomplete_cholesky),
                    static_cast<long>(ice::PressurePreconditioner::multigrid)}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(5.0)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_IceSaveRestore2d(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const DamBreak d = dam_break(n);
  ice::ExchangeCoefficients exchange = ice::ExchangeCoefficients::none(2);
  exchange.set(0, 1, 1.0e15, 0.0);
  ice::IceSolver<2> solver(d.grid, d.materials, exchange, ice::IceSolver<2>::Sides{},
                           Eigen::Vector2d(0.0, -9.81), d.state, ice::IceSolverOptions{});
  const double dt = 0.4 * d.grid.spacing()[0] / 1.5;
  std::vector<double> step_seconds;
  for (int s = 0; s < 5; ++s) {
    const auto start = std::chrono::steady_clock::now();
    solver.advance(dt);
    step_seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(step_seconds.begin(), step_seconds.begin() + 2, step_seconds.end());
  ice::SavedIceState<2> saved;
  solver.save_state(saved);  // the first save allocates
  for (auto _ : state) {
    solver.save_state(saved);
    solver.restore_state(saved);
    benchmark::ClobberMemory();
  }
  state.counters["in_steps"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * step_seconds[2],
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_IceSaveRestore2d)
    ->ArgNames({"cells_per_side"})
    ->Arg(316)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
BENCHMARK_MAIN();
