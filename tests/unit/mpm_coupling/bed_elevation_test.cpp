// The bed the shallow-water solver sees: the cell average of the particles'
// top envelope (Zheng et al., Algorithm 1, line 15).
#include "mpm/coupling/bed_elevation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <vector>

#include "particle_fixtures.hpp"

namespace mpm::coupling {
namespace {

TEST(MpmCouplingBedElevation, FlatToppedBlockGivesItsTopAndEmptyColumnsTheGridBottom2D) {
  const Grid<2> g = make_grid<2>(Vec<2>(0.0, -1.0), Vec<2>(0.05, 0.05), {20, 40}, ShapeKind::gimp);
  const auto surface = SurfaceGrid<2>::covering(g, {10});
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.2, -1.0), Vec<2>(0.8, 0.35), 0.025, 0.4, 2650.0, 0);
  const auto bed = bed_elevation(surface, particles, testing::porous_roles(), 1);
  ASSERT_EQ(bed.size(), 10u);
  for (int c = 0; c < 10; ++c) {
    const double expected = c >= 2 && c < 8 ? 0.35 : -1.0;
    EXPECT_NEAR(bed[static_cast<std::size_t>(c)], expected, 1e-12) << "column " << c;
  }
}

TEST(MpmCouplingBedElevation, FlatToppedBlockGivesItsTop3D) {
  const Grid<3> g = make_grid<3>(Vec<3>::Zero(), Vec<3>::Constant(0.1), {8, 6, 5}, ShapeKind::gimp);
  const auto surface = SurfaceGrid<3>::covering(g, {4, 3});
  Particles<3> particles;
  testing::add_block<3>(particles, Vec<3>(0.2, 0.0, 0.0), Vec<3>(0.8, 0.6, 0.3), 0.05, 0.4, 2650.0,
                        0);
  const auto bed = bed_elevation(surface, particles, testing::porous_roles(), 4);
  ASSERT_EQ(bed.size(), 12u);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) {
      const double expected = i == 0 ? 0.0 : 0.3;  // column 0 is empty
      EXPECT_NEAR(bed[static_cast<std::size_t>(j * 4 + i)], expected, 1e-12) << i << "," << j;
    }
}

TEST(MpmCouplingBedElevation, DoesNotJumpWhenAParticleCrossesAColumnEdge) {
  const Grid<2> g = make_grid<2>(Vec<2>::Zero(), Vec<2>(0.1, 0.1), {10, 10}, ShapeKind::gimp);
  const auto surface = SurfaceGrid<2>::covering(g, {10});
  Particles<2> particles;
  const double d = 0.05;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.5), d, 0.4, 2650.0, 0);
  testing::add_block<2>(particles, Vec<2>(0.3, 0.5), Vec<2>(0.3 + d, 0.5 + d), d, 0.4, 2650.0, 0);
  const std::size_t rider = particles.size() - 1;
  const auto roles = testing::porous_roles();
  std::vector<double> before = bed_elevation(surface, particles, roles, 1);
  const double step = 0.1 / 200.0;
  double largest_change = 0.0, naive_largest_change = 0.0;
  auto naive = [&] {  // the highest particle top among the particles centred in each column
    std::vector<double> top(10, 0.0);
    for (std::size_t p = 0; p < particles.size(); ++p) {
      const std::size_t c = surface.column_of(particles.position[p]);
      top[c] = std::max(top[c], particles.position[p][1] + particles.half_length[p][1]);
    }
    return top;
  };
  std::vector<double> naive_before = naive();
  for (int k = 0; k < 400; ++k) {  // across the edges at x = 0.4 and 0.5
    particles.position[rider][0] += step;
    const auto after = bed_elevation(surface, particles, roles, 1);
    const auto naive_after = naive();
    for (std::size_t c = 0; c < after.size(); ++c) {
      largest_change = std::max(largest_change, std::abs(after[c] - before[c]));
      naive_largest_change =
          std::max(naive_largest_change, std::abs(naive_after[c] - naive_before[c]));
    }
    before = after;
    naive_before = naive_after;
  }
  // Lipschitz in the particle position: height d over a move of `step` in a 0.1 m cell.
  const double bound = d * step / 0.1 * (1.0 + 1e-9);
  std::printf(
      "  largest change per move %.3e m (bound %.3e m); per-column maximum would jump %.3e m\n",
      largest_change, bound, naive_largest_change);
  EXPECT_LE(largest_change, bound);
  EXPECT_GT(naive_largest_change, 10.0 * bound);
}

// Cell averages of the upper envelope, exactly, by brute force: between
// consecutive breakpoints (plateau ends, cell edges) the envelope is the
// highest plateau over the midpoint.
std::vector<double> brute_force_bed(const SurfaceGrid<2>& surface, const Particles<2>& particles) {
  const double x0 = surface.origin[0], dx = surface.spacing[0];
  const int n = surface.cells[0];
  std::vector<double> breaks;
  for (int i = 0; i <= n; ++i) breaks.push_back(x0 + i * dx);
  for (std::size_t p = 0; p < particles.size(); ++p)
    for (double x : {particles.position[p][0] - particles.half_length[p][0],
                     particles.position[p][0] + particles.half_length[p][0]})
      if (x > x0 && x < x0 + n * dx) breaks.push_back(x);
  std::sort(breaks.begin(), breaks.end());
  std::vector<double> bed(static_cast<std::size_t>(n), 0.0);
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1], mid = 0.5 * (a + b);
    double top = surface.bottom;
    for (std::size_t p = 0; p < particles.size(); ++p)
      if (std::abs(mid - particles.position[p][0]) < particles.half_length[p][0])
        top = std::max(top, particles.position[p][1] + particles.half_length[p][1]);
    const auto cell =
        static_cast<std::size_t>(std::clamp(static_cast<int>((mid - x0) / dx), 0, n - 1));
    bed[cell] += top * (b - a) / dx;
  }
  return bed;
}

// A spread-out heap of points of mixed sizes, most of them buried: the
// envelope that skips the hidden ones is the brute-force envelope.
TEST(MpmCouplingBedElevation, MatchesTheBruteForceEnvelopeOfAJumbledHeap) {
  const Grid<2> g = make_grid<2>(Vec<2>::Zero(), Vec<2>(0.05, 0.05), {40, 20}, ShapeKind::gimp);
  const auto surface = SurfaceGrid<2>::covering(g, {25});
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.2, 0.0), Vec<2>(1.2, 0.3), 0.025, 0.4, 2650.0, 0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double x = particles.position[p][0];
    particles.position[p][0] = x + 0.6 * (x - 0.7) * unit(random) + 0.01 * (unit(random) - 0.5);
    particles.position[p][1] *= 0.5 + unit(random);
    particles.half_length[p] *= 0.5 + unit(random);
  }
  const auto bed = bed_elevation(surface, particles, testing::porous_roles(), 1);
  const auto exact = brute_force_bed(surface, particles);
  double largest_error = 0.0;
  for (std::size_t c = 0; c < bed.size(); ++c)
    largest_error = std::max(largest_error, std::abs(bed[c] - exact[c]));
  std::printf("  %zu points, largest difference from the brute-force envelope %.1e m\n",
              particles.size(), largest_error);
  EXPECT_LT(largest_error, 1e-12);
}

// The points of `particles` for which keep(p) holds.
template <int Dim, class Keep>
Particles<Dim> subset(const Particles<Dim>& particles, Keep keep) {
  Particles<Dim> part = particles;
  std::size_t kept = 0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (!keep(p)) continue;
    part.for_each_array([&](auto& array) { array[kept] = array[p]; });
    ++kept;
  }
  part.for_each_array([&](auto& array) { array.resize(kept); });
  return part;
}

// The same heap held by two ranks, cut at a height (as a decomposed MPM
// cuts its rows): the lower rank's bed from the plateaus both ranks share
// (the gather gives its own, then the upper rank's) is the whole heap's.
TEST(MpmCouplingBedElevation, TwoRanksCutAtAHeightGiveTheWholeHeapsBed) {
  const Grid<2> g = make_grid<2>(Vec<2>::Zero(), Vec<2>(0.05, 0.05), {40, 20}, ShapeKind::gimp);
  const auto surface = SurfaceGrid<2>::covering(g, {25});
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.2, 0.0), Vec<2>(1.2, 0.3), 0.025, 0.4, 2650.0, 0);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    particles.position[p][0] += 0.1 * (unit(random) - 0.5);
    particles.position[p][1] *= 0.5 + unit(random);
  }
  const auto roles = testing::porous_roles();
  const Particles<2> lower =
      subset(particles, [&](std::size_t p) { return particles.position[p][1] < 0.15; });
  const Particles<2> upper =
      subset(particles, [&](std::size_t p) { return particles.position[p][1] >= 0.15; });
  ASSERT_GT(lower.size(), 0u);
  ASSERT_GT(upper.size(), 0u);
  std::vector<double> upper_shares;
  const auto upper_bed = bed_elevation(surface, upper, roles, 1, [&](std::span<const double> mine) {
    upper_shares.assign(mine.begin(), mine.end());
    return std::vector<double>(mine.begin(), mine.end());
  });
  const auto bed = bed_elevation(surface, lower, roles, 1, [&](std::span<const double> mine) {
    std::vector<double> all(mine.begin(), mine.end());
    all.insert(all.end(), upper_shares.begin(), upper_shares.end());
    return all;
  });
  const auto whole = bed_elevation(surface, particles, roles, 1);
  double largest = 0.0;
  for (std::size_t c = 0; c < bed.size(); ++c)
    largest = std::max(largest, std::abs(bed[c] - whole[c]));
  std::printf("  two ranks against the whole heap: largest difference %.1e m\n", largest);
  EXPECT_LT(largest, 1e-12);
  // The upper rank alone does not see the lower rank's points.
  EXPECT_NE(upper_bed, whole);
}

TEST(MpmCouplingBedElevation, OnlyBedBodiesFormTheBed) {
  const Grid<2> g = make_grid<2>(Vec<2>::Zero(), Vec<2>(0.1, 0.1), {10, 10}, ShapeKind::gimp);
  const auto surface = SurfaceGrid<2>::covering(g, {5});
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.4), 0.05, 0.4, 2650.0, 0);
  testing::add_block<2>(particles, Vec<2>(0.0, 0.4), Vec<2>(1.0, 0.6), 0.05, 0.0, 1000.0, 1);
  auto roles = testing::porous_roles(2);
  roles[1].bed = false;
  for (double b : bed_elevation(surface, particles, roles, 1)) EXPECT_NEAR(b, 0.4, 1e-12);
}

}  // namespace
}  // namespace mpm::coupling
