#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "solver_1d_cases.hpp"

namespace {

using swe::FluxKind;
using swe::LimiterKind;

const FluxKind all_fluxes[] = {FluxKind::roe, FluxKind::hll, FluxKind::hllc};

swe::Scheme scheme(FluxKind flux, LimiterKind limiter = LimiterKind::van_leer) {
  swe::Scheme s;
  s.flux = flux;
  s.limiter = limiter;
  return s;
}

void run(swe::Solver1d& s, int steps) {
  for (int n = 0; n < steps; ++n) s.step(s.stable_time_step());
}

TEST(Solver1dConservation, ConstantStateStaysConstant) {
  for (FluxKind flux : all_fluxes) {
    const auto edges = swe_test::uneven_edges(40, 0.0, 2.0);
    const swe::Boundaries1d open{{swe::BoundaryKind::transmissive, 0.0},
                                 {swe::BoundaryKind::transmissive, 0.0}};
    swe::Solver1d s(edges, {}, scheme(flux), open);
    s.set_bed(std::vector<double>(40, -0.3));
    s.set_state(std::vector<double>(40, 0.8), std::vector<double>(40, 0.4), {});
    run(s, 50);
    for (std::size_t i = 0; i < 40; ++i) {
      EXPECT_NEAR(s.depth()[i], 0.8, 1e-14) << swe::to_string(flux) << " cell " << i;
      EXPECT_NEAR(s.discharge_x()[i], 0.4, 1e-14) << swe::to_string(flux) << " cell " << i;
    }
  }
}

TEST(Solver1dConservation, WallsKeepTheVolumeToRoundOffWithDryCells) {
  const std::size_t n = 60;
  const auto edges = swe_test::uneven_edges(n, 0.0, 3.0);
  const auto x = swe_test::centres(edges);
  std::vector<double> h(n), hu(n), bed(n);
  for (std::size_t i = 0; i < n; ++i) {
    bed[i] = 0.2 * std::sin(5.0 * x[i]) + 0.1 * x[i];
    h[i] = std::max(0.0, 0.4 + 0.3 * std::cos(11.0 * x[i]) - bed[i]);  // several dry patches
    if (i % 7 == 3) h[i] = 0.0;
    hu[i] = 0.2 * std::sin(13.0 * x[i]) * h[i];
  }
  ASSERT_GT(std::count(h.begin(), h.end(), 0.0), 5);
  for (FluxKind flux : all_fluxes) {
    swe::Solver1d s(edges, {}, scheme(flux), swe_test::walls());
    s.set_bed(bed);
    s.set_state(h, hu, {});
    const double v0 = s.totals().volume;
    for (int k = 0; k < 300; ++k) {
      s.step(s.stable_time_step());
      const auto d = s.depth();
      ASSERT_GE(*std::min_element(d.begin(), d.end()), 0.0)
          << swe::to_string(flux) << " step " << k;
    }
    EXPECT_NEAR(s.totals().volume, v0, 1e-13 * v0) << swe::to_string(flux);
  }
}

// Bed bump peaking at 0.8 m above a lake whose surface is 0.5 m: the top of
// the bump is dry.
TEST(Solver1dBalance, LakeAtRestWithAnEmergedBumpStaysAtRest) {
  const std::size_t n = 80;
  for (FluxKind flux : all_fluxes) {
    for (LimiterKind limiter :
         {LimiterKind::none, LimiterKind::van_leer, LimiterKind::monotonized_central}) {
      const auto edges = swe_test::uneven_edges(n, 0.0, 1.0);
      const auto x = swe_test::centres(edges);
      std::vector<double> h(n), bed(n);
      for (std::size_t i = 0; i < n; ++i) {
        bed[i] = std::max(0.0, 0.8 - 20.0 * (x[i] - 0.45) * (x[i] - 0.45));
        h[i] = std::max(0.0, 0.5 - bed[i]);
      }
      swe::Solver1d s(edges, {}, scheme(flux, limiter), swe_test::walls());
      s.set_bed(bed);
      s.set_state(h, std::vector<double>(n, 0.0), {});
      run(s, 200);
      EXPECT_LE(swe_test::max_abs_velocity(s), 1e-12)
          << swe::to_string(flux) << " " << swe::to_string(limiter);
      for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(s.depth()[i], h[i], 1e-13) << "cell " << i;
    }
  }
}

TEST(Solver1dBed, SetBedKeepsTheVolumeAndMovesTheSurface) {
  const std::size_t n = 20;
  swe::Solver1d s(swe_test::uneven_edges(n, 0.0, 1.0), {}, {}, swe_test::walls());
  s.set_state(std::vector<double>(n, 0.5), std::vector<double>(n, 0.0), {});
  const double v0 = s.totals().volume;
  std::vector<double> bed(n);
  for (std::size_t i = 0; i < n; ++i) bed[i] = 0.01 * static_cast<double>(i);
  s.set_bed(bed);
  EXPECT_DOUBLE_EQ(s.totals().volume, v0);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(s.depth()[i], 0.5);
    EXPECT_DOUBLE_EQ(s.depth()[i] + s.bed()[i], 0.5 + bed[i]);
  }
  // The raised surface now drives a flow down the slope (towards x = 0).
  s.step(s.stable_time_step());
  EXPECT_LT(s.totals().momentum_x, 0.0);
}

TEST(Solver1dSymmetry, MirroredProblemGivesTheMirroredSolution) {
  const std::size_t n = 50;
  const auto edges = swe_test::uneven_edges(n, 0.0, 2.0);
  std::vector<double> mirrored_edges(n + 1);
  for (std::size_t i = 0; i <= n; ++i) mirrored_edges[i] = -edges[n - i];
  const auto x = swe_test::centres(edges);
  std::vector<double> h(n), hu(n), bed(n);
  for (std::size_t i = 0; i < n; ++i) {
    bed[i] = 0.1 * std::sin(4.0 * x[i]);
    h[i] = x[i] < 0.7 ? 1.0 - bed[i] : (x[i] < 1.4 ? 0.3 : 0.0);
    hu[i] = 0.3 * h[i];
  }
  auto reversed = [](std::vector<double> v, double sign) {
    std::reverse(v.begin(), v.end());
    for (double& a : v) a *= sign;
    return v;
  };
  const swe::Boundaries1d b{{swe::BoundaryKind::fixed_depth, 1.0}, {swe::BoundaryKind::wall, 0.0}};
  const swe::Boundaries1d mirrored_b{b.right, b.left};
  for (FluxKind flux : all_fluxes) {
    swe::Solver1d s(edges, {}, scheme(flux), b);
    swe::Solver1d m(mirrored_edges, {}, scheme(flux), mirrored_b);
    s.set_bed(bed);
    s.set_state(h, hu, {});
    m.set_bed(reversed(bed, 1.0));
    m.set_state(reversed(h, 1.0), reversed(hu, -1.0), {});
    for (int k = 0; k < 100; ++k) {
      const double dt = s.stable_time_step();
      ASSERT_NEAR(m.stable_time_step(), dt, 1e-14 * dt);
      s.step(dt);
      m.step(dt);
    }
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_NEAR(m.depth()[n - 1 - i], s.depth()[i], 1e-12)
          << swe::to_string(flux) << " cell " << i;
      EXPECT_NEAR(m.discharge_x()[n - 1 - i], -s.discharge_x()[i], 1e-12)
          << swe::to_string(flux) << " cell " << i;
    }
  }
}

TEST(Solver1dPositivity, DryBedDamBreakKeepsDepthsNonNegative) {
  const std::size_t n = 100;
  const auto edges = swe_test::uneven_edges(n, 0.0, 1.0);
  const auto x = swe_test::centres(edges);
  std::vector<double> h(n), bed(n);
  for (std::size_t i = 0; i < n; ++i) {
    h[i] = x[i] < 0.3 ? 1.0 : 0.0;
    bed[i] = 0.05 * std::sin(20.0 * x[i]);
  }
  for (FluxKind flux : all_fluxes) {
    for (LimiterKind limiter : {LimiterKind::van_leer, LimiterKind::monotonized_central}) {
      swe::Solver1d s(edges, {}, scheme(flux, limiter), swe_test::walls());
      s.set_bed(bed);
      s.set_state(h, std::vector<double>(n, 0.0), {});
      const double v0 = s.totals().volume;
      for (int k = 0; k < 400; ++k) {
        s.step(s.stable_time_step());
        const auto d = s.depth();
        ASSERT_GE(*std::min_element(d.begin(), d.end()), 0.0)
            << swe::to_string(flux) << " step " << k;
        for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(std::isfinite(s.discharge_x()[i]));
      }
      EXPECT_NEAR(s.totals().volume, v0, 1e-13 * v0);
    }
  }
}

}  // namespace
