#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "swe/solver_1d.hpp"

// A lake at rest (surface 0.5 m) over a bed bump that rises to 0.8 m, so its
// top is dry, between walls: the well-balanced scheme keeps it at rest.
namespace {

std::vector<double> edges_of(std::size_t n, bool uneven) {
  std::vector<double> e{0.0};
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(n);
    e.push_back(e.back() +
                (uneven ? (1.0 + 0.6 * std::sin(9.0 * s)) * (s < 0.4 ? 1.0 : 2.3) : 1.0));
  }
  for (double& x : e) x /= e.back();
  return e;
}

TEST(LakeAtRest, EmergedBumpStaysAtRestFor1000Steps) {
  constexpr std::size_t n = 200;
  constexpr double surface = 0.5, tolerance = 1e-12;
  for (bool uneven : {false, true}) {
    for (auto flux : {swe::FluxKind::roe, swe::FluxKind::hll, swe::FluxKind::hllc}) {
      const auto edges = edges_of(n, uneven);
      std::vector<double> bed(n), h(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double x = 0.5 * (edges[i] + edges[i + 1]);
        bed[i] = std::max(0.0, 0.8 - 15.0 * (x - 0.55) * (x - 0.55));
        h[i] = std::max(0.0, surface - bed[i]);
      }
      swe::Scheme scheme;
      scheme.flux = flux;
      swe::Solver1d s(edges, {}, scheme,
                      {{swe::BoundaryKind::wall, 0.0}, {swe::BoundaryKind::wall, 0.0}});
      s.set_bed(bed);
      s.set_state(h, std::vector<double>(n, 0.0), {});
      const double dt = s.stable_time_step();
      for (int k = 0; k < 1000; ++k) s.step(dt);
      double max_u = 0.0, max_dh = 0.0;
      std::size_t dry = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double d = s.depth()[i];
        if (d >= s.physics().dry_depth) max_u = std::max(max_u, std::abs(s.discharge_x()[i] / d));
        max_dh = std::max(max_dh, std::abs(d - h[i]));
        dry += h[i] == 0.0 ? 1 : 0;
      }
      fmt::print(
          "{:<12} {:<5} dry cells {:>3}: max |u| = {:.2e} m/s (tolerance {:.0e}), max |dh| = "
          "{:.2e} m\n",
          uneven ? "non-uniform" : "uniform", swe::to_string(flux), dry, max_u, tolerance, max_dh);
      EXPECT_GT(dry, 10u);
      EXPECT_LE(max_u, tolerance);
    }
  }
}

}  // namespace
