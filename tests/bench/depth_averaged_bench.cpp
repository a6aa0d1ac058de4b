// Depth-averaged mass throughput (van den Bout et al., OpenLISEM Hazard):
// particle-updates per second of whole steps (P2G, thrust, walls, friction,
// G2P, fragmentation, splitting) of a cohesionless mound spreading down a
// 30 deg plane, 1e5 and 1e6 points (3 x 3 per cell, a round mound), one thread (the
// depth-averaged solver has no OpenMP loops yet). Every repetition starts
// from the same mound at rest and times its first steps at the stable step,
// so repetitions measure the same work.
//
// Counters: items_per_second (particle-updates/s), points (at the end of the
// timed steps: stretched points split).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "mpm/depth_averaged/depth_averaged_solver.hpp"

namespace {

using mpm::Vec;

constexpr int timed_steps = 10;

mpm::DepthAveragedSolver mound(int mound_cells) {
  const double dx = 1.0;
  const int cells = 2 * mound_cells;
  mpm::DepthAveragedSettings s;
  s.grid.origin = Vec<2>::Zero();
  s.grid.spacing = Vec<2>::Constant(dx);
  s.grid.cells = {cells, cells};
  s.terrain = mpm::Terrain(30.0 * std::numbers::pi / 180.0);
  s.earth_pressure = mpm::EarthPressure(mpm::EarthPressureModel::rankine);
  mpm::DepthAveragedMaterial m;
  m.name = "debris";
  m.density = 2000.0;
  m.internal_friction_angle = 30.0 * std::numbers::pi / 180.0;
  m.basal_friction_angle = 20.0 * std::numbers::pi / 180.0;
  const double lower = 0.5 * mound_cells, upper = 1.5 * mound_cells, radius = 0.5 * mound_cells;
  mpm::DepthAveragedParticles p;
  p.seed(
      {lower, lower}, {upper, upper}, s.grid.spacing, 3,
      [&](const Vec<2>& x) {
        const double r = (x - Vec<2>::Constant(mound_cells)).norm() / radius;
        return 5.0 * (1.0 - r * r);
      },
      m.density, 0);
  return mpm::DepthAveragedSolver(s, {m}, p);
}

void DepthAveragedSteps(benchmark::State& state) {
  const int mound_cells = static_cast<int>(state.range(0));
  double updates = 0.0;
  std::size_t points = 0;
  for (auto _ : state) {
    state.PauseTiming();
    mpm::DepthAveragedSolver solver = mound(mound_cells);
    const double dt = solver.stable_time_step();
    state.ResumeTiming();
    for (int k = 0; k < timed_steps; ++k) {
      updates += static_cast<double>(solver.particles().size());
      solver.step(dt);
    }
    points = solver.particles().size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(updates));
  state.counters["points"] = static_cast<double>(points);
}

// A mound inscribed in 119 x 119 cells of 9 points: 1.0e5 points; 376 x 376: 1.0e6.
BENCHMARK(DepthAveragedSteps)->Arg(119)->Arg(376)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
