// The two-phase mode of the 2D shallow water (van den Bout et al., OpenLISEM
// Hazard, eqs. 61-65): a "0-D" uniform box (transmissive sides: a uniform
// state stays uniform bit for bit, as a periodic box would) with a solid
// layer moving relative to the fluid, against the exact linear relaxation
// du(t) = du0 exp(-C mu t / (1 + V mu)), mu = 1/(alpha_c rho_c) + 1/(alpha_u
// rho_f), C constant (constant smoothing speed); and a lake at rest over a
// bump made of solids.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "swe/solver_2d.hpp"
#include "swe/two_phase/two_phase_exchange.hpp"

namespace {

struct Box {
  double h_f = 1.0, h_s = 0.5, rho_c = 2000.0;
  std::array<double, 2> u_f{0.3, -0.2}, u_s{1.0, 0.5};
};

void relax(bool virtual_mass, double grain_size, double smoothing_speed, double steps_relaxation,
           const char* label, double dt_times_rate_min) {
  const Box b;
  const int n = 4;
  const std::size_t cells = 16;
  const swe::Boundary t{swe::BoundaryKind::transmissive, 0.0};
  swe::Solver2d solver({{0.0, 0.0}, {10.0, 10.0}, {n, n}}, {}, {}, {t, t, t, t});
  solver.set_state(std::vector<double>(cells, b.h_f), std::vector<double>(cells, b.h_f * b.u_f[0]),
                   std::vector<double>(cells, b.h_f * b.u_f[1]));
  swe::SolidLayer layer = swe::empty_solid_layer(cells, b.rho_c);
  layer.depth.assign(cells, b.h_s);
  layer.velocity_x.assign(cells, b.u_s[0]);
  layer.velocity_y.assign(cells, b.u_s[1]);
  swe::TwoPhaseParameters p;
  p.drag.exponent = 1.0;
  p.drag.smoothing_speed = smoothing_speed;
  p.drag.grain_size = grain_size;
  p.virtual_mass = virtual_mass;
  swe::TwoPhaseExchange exchange(solver, p, {}, layer, std::vector<double>(cells, 0.0));
  exchange.apply_bed(solver);

  const double rho_f = 1000.0, H = b.h_s + b.h_f;
  const double alpha_c = b.h_s / H, alpha_u = b.h_f / H;
  const auto mixture = swe::cell_mixture(b.h_s, b.h_f, b.rho_c, 0.0, p, rho_f);
  p.drag.gravity = 9.81;
  const double C = cosim::exchange::generalised_drag_coefficient(mixture, p.drag, b.u_s, b.u_f);
  const double mu = 1.0 / (alpha_c * b.rho_c) + 1.0 / (alpha_u * rho_f);
  const double V =
      virtual_mass ? alpha_c * rho_f * cosim::exchange::virtual_mass_coefficient(mixture) : 0.0;
  const double rate = C * mu / (1.0 + V * mu);
  const double dt = std::min(solver.stable_time_step(), steps_relaxation / rate);
  const double total0 =
      rho_f * b.h_f * (b.u_f[0] + b.u_f[1]) + b.rho_c * b.h_s * (b.u_s[0] + b.u_s[1]);
  double time = 0.0, worst = 0.0, worst_momentum = 0.0;
  for (int s = 0; s < 40; ++s) {
    solver.step(dt);
    exchange.after_step(solver, dt);
    time += dt;
    for (std::size_t c = 0; c < cells; ++c)
      for (int a = 0; a < 2; ++a) {
        const auto k = static_cast<std::size_t>(a);
        const double u_f = (a == 0 ? solver.discharge_x()[c] : solver.discharge_y()[c]) / b.h_f;
        const double u_s = a == 0 ? exchange.layer().velocity_x[c] : exchange.layer().velocity_y[c];
        const double du0 = b.u_f[k] - b.u_s[k];
        const double exact = du0 * std::exp(-rate * time);
        // relative to the exact difference; once that is below 1e-9 du0, relative to
        // 1e-9 du0 (the velocities' own round-off, ~1e-16 m/s, is then what is left)
        worst = std::max(
            worst, std::abs((u_f - u_s) - exact) / std::max(std::abs(exact), 1e-9 * std::abs(du0)));
      }
    double total = 0.0;
    for (std::size_t c = 0; c < cells; ++c)
      total +=
          (rho_f * (solver.discharge_x()[c] + solver.discharge_y()[c]) +
           b.rho_c * b.h_s * (exchange.layer().velocity_x[c] + exchange.layer().velocity_y[c])) /
          static_cast<double>(cells);
    worst_momentum = std::max(worst_momentum, std::abs(total - total0) / std::abs(total0));
  }
  fmt::print(
      "two-phase 0-D box, {}: C = {:.4g}, dt C mu / (1 + V mu) = {:.3g}, {} steps: max "
      "relative error of du {:.2e} (tolerance 1e-6), momentum {:.2e} (tolerance 1e-13)\n",
      label, C, rate * dt, 40, worst, worst_momentum);
  EXPECT_GE(rate * dt, dt_times_rate_min);
  EXPECT_LE(worst, 1e-6);
  EXPECT_LE(worst_momentum, 1e-13);
}

TEST(SweTwoPhaseBox, RelaxesAsTheExactSolution) {
  relax(false, 1e-3, 0.5, 0.1, "linear drag", 0.0);
}
TEST(SweTwoPhaseBox, RelaxesAsTheExactSolutionWithVirtualMass) {
  relax(true, 1e-3, 0.5, 0.1, "linear drag + virtual mass", 0.0);
}
TEST(SweTwoPhaseBox, StaysStableAtAThousandRelaxationsPerStep) {
  relax(false, 1e-6, 1e-6, 1e3, "stiff (fine grains, K = 1e-6 m/s)", 1e3 * (1.0 - 1e-12));
}

TEST(SweTwoPhaseLakeAtRest, StaysAtRestOverABumpOfSolids) {
  const int n = 60, steps = 500;
  const std::size_t cells = static_cast<std::size_t>(n * n);
  const double surface = 0.5, tolerance = 1e-12, dx = 0.02;
  const swe::Boundary wall{swe::BoundaryKind::wall, 0.0};
  swe::Solver2d solver({{0.0, 0.0}, {dx, dx}, {n, n}}, {}, {}, {wall, wall, wall, wall});
  std::vector<double> base(cells), depth(cells);
  swe::SolidLayer layer = swe::empty_solid_layer(cells, 1900.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto c = static_cast<std::size_t>(i + n * j);
      const double x = (i + 0.5) * dx, y = (j + 0.5) * dx;
      base[c] = 0.1 * std::sin(7.0 * x) * std::sin(5.0 * y);
      // a solid bump emerging above the surface, and a submerged one
      layer.depth[c] = 0.7 * std::exp(-30.0 * ((x - 0.4) * (x - 0.4) + (y - 0.6) * (y - 0.6))) +
                       0.2 * std::exp(-40.0 * ((x - 0.9) * (x - 0.9) + (y - 0.3) * (y - 0.3)));
      depth[c] = std::max(0.0, surface - base[c] - layer.depth[c]);
    }
  swe::TwoPhaseExchange exchange(solver, {}, {}, layer, base);
  exchange.apply_bed(solver);
  solver.set_state(depth, {}, {});
  const auto dry = std::count(depth.begin(), depth.end(), 0.0);
  ASSERT_GT(dry, 10);
  for (int s = 0; s < steps; ++s) {
    const double dt = solver.stable_time_step();
    solver.step(dt);
    exchange.after_step(solver, dt);
  }
  double max_speed = 0.0, max_solid = 0.0, max_change = 0.0;
  for (std::size_t c = 0; c < cells; ++c) {
    const double h = solver.depth()[c];
    if (h >= solver.physics().dry_depth)
      max_speed = std::max({max_speed, std::abs(solver.discharge_x()[c] / h),
                            std::abs(solver.discharge_y()[c] / h)});
    max_solid = std::max({max_solid, std::abs(exchange.layer().velocity_x[c]),
                          std::abs(exchange.layer().velocity_y[c])});
    max_change = std::max(max_change, std::abs(h - depth[c]));
  }
  fmt::print(
      "lake at rest over solids, {} x {} cells ({} dry), {} steps: max fluid speed {:.3e} "
      "m/s, max solid speed {:.3e} m/s (tolerance {:.0e}), max depth change {:.3e} m\n",
      n, n, dry, steps, max_speed, max_solid, tolerance, max_change);
  EXPECT_LE(max_speed, tolerance);
  EXPECT_LE(max_solid, tolerance);
  EXPECT_LE(max_change, 1e-12);
}

}  // namespace
