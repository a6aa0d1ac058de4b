#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "bench/shallow_water_dam_break.hpp"
#include "swe/solver_1d.hpp"

// Stoker's dam break as in Zheng et al., Sec. 4.2: [0, 1] m, h = 1 m for
// x <= 0.5 m and 0.5 m beyond, at rest, frictionless, transmissive ends,
// compared at t = 0.1 s with the exact solution. C_r = 0.5 (our scheme's
// positivity bound; the paper uses 0.75), van Leer slopes, Roe (the paper's
// flux) and HLL.
namespace {

constexpr double g = 9.81, t_end = 0.1;

std::vector<double> uniform(std::size_t n) {
  std::vector<double> e(n + 1);
  for (std::size_t i = 0; i <= n; ++i) e[i] = static_cast<double>(i) / static_cast<double>(n);
  return e;
}

// The paper's non-uniform spacings (dx_fine in [0.25, 0.75], dx_coarse
// elsewhere) do not divide those intervals; we take the nearest whole number
// of cells in each interval and spread it evenly: 0.016/0.03 m -> 31 cells of
// 0.01613 m and 2 x 8 of 0.03125 m (47 cells); 0.008/0.015 m -> 63 cells of
// 0.00794 m and 2 x 17 of 0.01471 m (97 cells).
std::vector<double> paper_non_uniform(double dx_fine, double dx_coarse) {
  const auto fine = static_cast<std::size_t>(std::lround(0.5 / dx_fine));
  const auto coarse = static_cast<std::size_t>(std::lround(0.25 / dx_coarse));
  std::vector<double> e{0.0};
  auto fill = [&](double a, double b, std::size_t n) {
    for (std::size_t i = 1; i <= n; ++i)
      e.push_back(a + (b - a) * static_cast<double>(i) / static_cast<double>(n));
  };
  fill(0.0, 0.25, coarse);
  fill(0.25, 0.75, fine);
  fill(0.75, 1.0, coarse);
  return e;
}

double l1_depth_error(const swe::Solver1d& s, const cosim::bench::ExactDamBreak& exact) {
  constexpr int samples = 400;
  double error = 0.0;
  const auto& e = s.edges();
  for (std::size_t i = 0; i < s.cell_count(); ++i) {
    const double w = e[i + 1] - e[i];
    double sum = 0.0;
    for (int k = 0; k < samples; ++k) {
      const double x = e[i] + w * (k + 0.5) / samples;
      sum += std::abs(s.depth()[i] - exact.depth(x, t_end));
    }
    error += sum * w / samples;
  }
  return error;
}

double run_stoker(const std::vector<double>& edges, swe::FluxKind flux,
                  const cosim::bench::ExactDamBreak& exact) {
  swe::Scheme scheme;
  scheme.flux = flux;
  scheme.limiter = swe::LimiterKind::van_leer;
  scheme.courant = 0.5;
  swe::Physics physics;
  physics.gravity = g;
  const swe::Boundaries1d open{{swe::BoundaryKind::transmissive, 0.0},
                               {swe::BoundaryKind::transmissive, 0.0}};
  swe::Solver1d s(edges, physics, scheme, open);
  std::vector<double> h(s.cell_count());
  for (std::size_t i = 0; i < h.size(); ++i)
    h[i] = 0.5 * (edges[i] + edges[i + 1]) <= 0.5 ? 1.0 : 0.5;
  s.set_state(h, std::vector<double>(h.size(), 0.0), {});
  double t = 0.0;
  while (t < t_end) {
    const double dt = std::min(s.stable_time_step(), t_end - t);
    s.step(dt);
    t = (t_end - t - dt < 1e-14) ? t_end : t + dt;
  }
  return l1_depth_error(s, exact);
}

TEST(Stoker, ShockSpeedMatchesThePaper) {
  const cosim::bench::ExactDamBreak exact(1.0, 0.5, 0.5, g);
  fmt::print(
      "exact middle state h* = {:.6f} m, u* = {:.6f} m/s, shock speed {:.5f} m/s (paper C_s = "
      "2.9579)\n",
      exact.middle_depth(), exact.middle_velocity(), exact.front_speed());
  EXPECT_LT(std::abs(exact.front_speed() - 2.9579), 1e-3);
  // The paper's closed forms for the middle state from C_s.
  const double root = std::sqrt(1.0 + 16.0 * exact.front_speed() * exact.front_speed() / g);
  EXPECT_NEAR(exact.middle_depth(), 0.25 * (root - 1.0), 1e-12);
  EXPECT_NEAR(exact.middle_velocity(),
              exact.front_speed() - g / (8.0 * exact.front_speed()) * (1.0 + root), 1e-12);
}

TEST(Stoker, L1DepthErrorOnThePapersMeshes) {
  const cosim::bench::ExactDamBreak exact(1.0, 0.5, 0.5, g);
  struct Mesh {
    std::string name, family;
    std::vector<double> edges;
  };
  const std::vector<Mesh> meshes{
      {"uniform 50", "uniform", uniform(50)},
      {"uniform 100", "uniform", uniform(100)},
      {"non-uniform 0.016/0.03", "non-uniform", paper_non_uniform(0.016, 0.03)},
      {"non-uniform 0.008/0.015", "non-uniform", paper_non_uniform(0.008, 0.015)}};
  std::map<std::string, std::vector<double>> errors;  // family + flux -> coarse, fine
  fmt::print("{:<26} {:>6} {:>14} {:>14}\n", "mesh", "cells", "L1(h) Roe [m]", "L1(h) HLL [m]");
  for (const Mesh& m : meshes) {
    const double roe = run_stoker(m.edges, swe::FluxKind::roe, exact);
    const double hll = run_stoker(m.edges, swe::FluxKind::hll, exact);
    fmt::print("{:<26} {:>6} {:>14.3e} {:>14.3e}\n", m.name, m.edges.size() - 1, roe, hll);
    errors[m.family + " roe"].push_back(roe);
    errors[m.family + " hll"].push_back(hll);
    if (m.name == "uniform 100") {
      fmt::print("  tolerance on 100 uniform cells: 5.0e-03 m\n");
      EXPECT_LE(roe, 5e-3);
      EXPECT_LE(hll, 5e-3);
    }
  }
  for (const auto& [family, e] : errors) {
    fmt::print("{}: coarse {:.3e} m -> fine {:.3e} m (ratio {:.2f})\n", family, e[0], e[1],
               e[0] / e[1]);
    EXPECT_LT(e[1], e[0]) << family;
  }
}

}  // namespace
