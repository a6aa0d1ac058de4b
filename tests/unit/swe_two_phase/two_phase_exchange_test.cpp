#include "swe/two_phase/two_phase_exchange.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "input_error.hpp"
#include "swe/solver_1d.hpp"
#include "swe/solver_2d.hpp"

namespace swe {
namespace {

Boundaries2d transmissive() {
  const Boundary b{BoundaryKind::transmissive, 0.0};
  return {b, b, b, b};
}

TEST(SweTwoPhaseExchange, RaisesTheBedByTheSolidsKeepingTheDepths) {
  Solver2d solver({{0.0, 0.0}, {1.0, 1.0}, {4, 3}}, {}, {}, transmissive());
  solver.set_state(std::vector<double>(12, 0.5), {}, {});
  SolidLayer layer = empty_solid_layer(12, 2000.0);
  layer.depth[5] = 0.2;
  TwoPhaseExchange exchange(solver, {}, {}, layer, std::vector<double>(12, 1.0));
  exchange.apply_bed(solver);
  EXPECT_EQ(solver.bed()[5], 1.2);
  EXPECT_EQ(solver.bed()[4], 1.0);
  EXPECT_EQ(solver.depth()[5], 0.5);
}

TEST(SweTwoPhaseExchange, KeepsTheMomentumOfFluidAndSolidsWithManningOff) {
  const std::size_t n = 16;
  Solver2d solver({{0.0, 0.0}, {2.0, 2.0}, {4, 4}}, {}, {}, transmissive());
  solver.set_state(std::vector<double>(n, 0.8), std::vector<double>(n, 0.8 * 0.3),
                   std::vector<double>(n, -0.8 * 0.1));
  SolidLayer layer = empty_solid_layer(n, 1800.0);
  layer.depth.assign(n, 0.4);
  layer.velocity_x.assign(n, 1.5);
  layer.velocity_y.assign(n, 0.7);
  TwoPhaseExchange exchange(solver, {}, {}, layer, std::vector<double>(n, 0.0));
  exchange.apply_bed(solver);
  auto total = [&](int axis) {
    const Totals t = solver.totals();
    double solid = 0.0;
    for (std::size_t c = 0; c < n; ++c)
      solid += 1800.0 * 0.4 * 4.0 *
               (axis == 0 ? exchange.layer().velocity_x[c] : exchange.layer().velocity_y[c]);
    return 1000.0 * (axis == 0 ? t.momentum_x : t.momentum_y) + solid;
  };
  const double px = total(0), py = total(1);
  for (int s = 0; s < 20; ++s) {
    const double dt = solver.stable_time_step();
    solver.step(dt);
    exchange.after_step(solver, dt);
  }
  const double error =
      std::max(std::abs(total(0) - px) / std::abs(px), std::abs(total(1) - py) / std::abs(py));
  fmt::print(
      "exchange on a 4 x 4 solver, 20 steps: relative change of the total momentum "
      "{:.2e} (tolerance 1e-13)\n",
      error);
  EXPECT_LE(error, 1e-13);
  EXPECT_NE(exchange.impulse_x()[0], 0.0);
}

TEST(SweTwoPhaseExchange, ManningStillActsOnTheFluid) {
  const std::size_t n = 9;
  Physics physics;
  physics.manning = 0.03;
  Solver2d with(Grid2d{{0.0, 0.0}, {1.0, 1.0}, {3, 3}}, physics, {}, transmissive());
  Solver2d plain(Grid2d{{0.0, 0.0}, {1.0, 1.0}, {3, 3}}, physics, {}, transmissive());
  for (Solver2d* s : {&with, &plain}) {
    s->set_bed(std::vector<double>(n, 0.3));
    s->set_state(std::vector<double>(n, 0.5), std::vector<double>(n, 0.5), {});
  }
  // solids moving with the fluid: only Manning separates them in the first step
  SolidLayer layer = empty_solid_layer(n, 2000.0);
  layer.depth.assign(n, 0.3);
  layer.velocity_x.assign(n, 1.0);
  TwoPhaseExchange exchange(with, {}, {}, layer, std::vector<double>(n, 0.0));
  exchange.apply_bed(with);
  const double dt = 0.05;
  with.step(dt);
  plain.step(dt);
  const double fluid_after_manning = 1000.0 * plain.totals().momentum_x;
  exchange.after_step(with, dt);
  double solid = 0.0;
  for (std::size_t c = 0; c < n; ++c) solid += 2000.0 * 0.3 * exchange.layer().velocity_x[c];
  const double total = 1000.0 * with.totals().momentum_x + solid;
  const double expected = fluid_after_manning + 2000.0 * 0.3 * 1.0 * static_cast<double>(n);
  const double error = std::abs(total - expected) / expected;
  fmt::print(
      "Manning with a solid layer: total momentum vs Manning-only fluid + solids, "
      "relative {:.2e} (tolerance 1e-13); fluid lost {:.3e} kg m/s to friction\n",
      error, 1000.0 * 0.5 * 9.0 - fluid_after_manning);
  EXPECT_LT(fluid_after_manning, 1000.0 * 0.5 * 9.0);
  EXPECT_LE(error, 1e-13);
}

TEST(SweTwoPhaseExchange, RestoresASavedWindow) {
  const std::size_t n = 4;
  Solver2d solver({{0.0, 0.0}, {1.0, 1.0}, {2, 2}}, {}, {}, transmissive());
  solver.set_state(std::vector<double>(n, 0.5), {}, {});
  SolidLayer layer = empty_solid_layer(n, 2000.0);
  layer.depth.assign(n, 0.2);
  layer.velocity_x.assign(n, 1.0);
  TwoPhaseExchange exchange(solver, {}, {}, layer, std::vector<double>(n, 0.0));
  exchange.save_state();
  exchange.after_step(solver, 0.1);
  EXPECT_NE(exchange.layer().velocity_x[0], 1.0);
  exchange.restore_state();
  EXPECT_EQ(exchange.layer().velocity_x[0], 1.0);
  EXPECT_EQ(exchange.impulse_x()[0], 0.0);
}

TEST(SweTwoPhaseExchange, RefusesA1dSolverAndBadDragParameters) {
  Solver1d line(std::vector<double>{0.0, 1.0, 2.0}, {}, {}, {});
  std::string message = cosim::testing::input_error_message([&] {
    TwoPhaseExchange e(line, {}, {}, empty_solid_layer(2, 2000.0), {0.0, 0.0});
  });
  EXPECT_NE(message.find("2D"), std::string::npos) << message;
  Solver2d solver({{0.0, 0.0}, {1.0, 1.0}, {2, 2}}, {}, {}, transmissive());
  TwoPhaseParameters p;
  p.drag.exponent = 3.0;
  message = cosim::testing::input_error_message([&] {
    TwoPhaseExchange e(solver, p, {}, empty_solid_layer(4, 2000.0), std::vector<double>(4, 0.0));
  });
  EXPECT_NE(message.find("exponent j"), std::string::npos) << message;
}

}  // namespace
}  // namespace swe
