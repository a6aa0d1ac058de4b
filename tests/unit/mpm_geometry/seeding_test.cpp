// Seeding regions with particles: regular sub-cell centres and the R_d
// quasi-random sequence.
#include "mpm/geometry/seeding.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cosim/error.hpp"
#include "mpm/geometry/box.hpp"
#include "mpm/geometry/polygon.hpp"
#include "mpm/geometry/polyhedron.hpp"

namespace mpm {
namespace {

template <int Dim>
GridGeometry<Dim> grid(double h, int cells) {
  GridGeometry<Dim> g;
  g.origin = Vec<Dim>::Constant(-1.0);
  g.spacing = Vec<Dim>::Constant(h);
  g.cells.fill(cells);
  return g;
}

TEST(Seeding, BoxAlignedWithCellsGetsItsVolumeExactly) {
  const auto g2 = grid<2>(0.1, 40);
  const Box<2> box{Vec<2>(-0.5, 0.0), Vec<2>(0.3, 0.7)};
  for (int n : {1, 2, 3}) {
    const auto seeded = seed_region(box, g2, SeedingPattern{SeedingPattern::Kind::regular, n, 0});
    EXPECT_EQ(seeded.size(), static_cast<std::size_t>(8 * 7 * n * n));
    EXPECT_NEAR(seeded.total_volume(), box.volume(), 1e-13);
    for (std::size_t p = 0; p < seeded.size(); ++p) {
      EXPECT_TRUE(box.contains(seeded.positions[p]));
      EXPECT_NEAR(seeded.half_lengths[p].x(), 0.1 / (2 * n), 1e-15);
    }
  }
  const auto g3 = grid<3>(0.25, 12);
  const Box<3> box3{Vec<3>(-0.5, -0.5, 0.0), Vec<3>(0.5, 0.0, 1.0)};
  const auto seeded3 = seed_region(box3, g3, SeedingPattern{SeedingPattern::Kind::regular, 2, 0});
  EXPECT_EQ(seeded3.size(), static_cast<std::size_t>(4 * 2 * 4 * 8));
  EXPECT_NEAR(seeded3.total_volume(), box3.volume(), 1e-13);
}

TEST(Seeding, RegularPatternIsSubCellCentresXFastest) {
  const auto pattern = cell_pattern<2>(SeedingPattern{SeedingPattern::Kind::regular, 2, 0});
  ASSERT_EQ(pattern.size(), 4u);
  EXPECT_EQ(pattern[0], Vec<2>(0.25, 0.25));
  EXPECT_EQ(pattern[1], Vec<2>(0.75, 0.25));
  EXPECT_EQ(pattern[2], Vec<2>(0.25, 0.75));
  EXPECT_EQ(pattern[3], Vec<2>(0.75, 0.75));
}

TEST(Seeding, PolygonAreaWithinResolution) {
  const Polygon triangle({Vec<2>(-0.83, -0.71), Vec<2>(0.77, -0.52), Vec<2>(0.11, 0.93)});
  const auto g = grid<2>(0.05, 40);
  for (auto kind : {SeedingPattern::Kind::regular, SeedingPattern::Kind::quasi_random}) {
    const auto seeded = seed_region(triangle, g, SeedingPattern{kind, 2, 0});
    const double error = std::abs(seeded.total_volume() - triangle.area()) / triangle.area();
    std::printf("triangle area %.5f, seeded %.5f, relative error %.2e (tolerance 2e-2)\n",
                triangle.area(), seeded.total_volume(), error);
    EXPECT_LT(error, 0.02);
    for (const auto& x : seeded.positions) EXPECT_TRUE(triangle.contains(x));
  }
}

TEST(Seeding, PolyhedronVolumeWithinResolution) {
  const std::vector<Vec<3>> v{Vec<3>(-0.9, -0.8, -0.7), Vec<3>(0.8, -0.6, -0.8),
                              Vec<3>(-0.5, 0.9, -0.6), Vec<3>(-0.4, -0.3, 0.9)};
  const Polyhedron tet(v, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  const auto g = grid<3>(0.1, 20);
  const auto seeded = seed_region(tet, g, SeedingPattern{SeedingPattern::Kind::regular, 2, 0});
  const double error = std::abs(seeded.total_volume() - tet.volume()) / tet.volume();
  std::printf("tetrahedron volume %.5f, seeded %.5f, relative error %.2e (tolerance 3e-2)\n",
              tet.volume(), seeded.total_volume(), error);
  EXPECT_LT(error, 0.03);
}

TEST(Seeding, RegionsPartlyOutsideTheGridKeepOnlyInsidePoints) {
  const auto g = grid<2>(0.1, 10);  // [-1, 0]^2
  const Box<2> box{Vec<2>(-0.5, -0.5), Vec<2>(3.0, 3.0)};
  const auto seeded = seed_region(box, g, SeedingPattern{});
  EXPECT_NEAR(seeded.total_volume(), 0.25, 1e-13);
  const Box<2> away{Vec<2>(5.0, 5.0), Vec<2>(6.0, 6.0)};
  EXPECT_EQ(seed_region(away, g, SeedingPattern{}).size(), 0u);
}

TEST(Seeding, RSequenceRoots) {
  EXPECT_NEAR(r_sequence_root(1), (1.0 + std::sqrt(5.0)) / 2.0, 1e-15);  // golden ratio
  // plastic constant, closed form of van den Bout et al. after eq. 88 (its
  // decimal value there, 1.32471795572, has transposed digits: 1.3247179572)
  const double plastic =
      std::cbrt((9.0 + std::sqrt(69.0)) / 18.0) + std::cbrt((9.0 - std::sqrt(69.0)) / 18.0);
  EXPECT_NEAR(r_sequence_root(2), plastic, 1e-15);
  EXPECT_NEAR(r_sequence_root(2), 1.3247179572, 1e-10);
  const double phi3 = r_sequence_root(3);
  EXPECT_NEAR(std::pow(phi3, 4), phi3 + 1.0, 1e-14);
  EXPECT_NEAR(phi3, 1.2207440846, 1e-10);
}

template <int Dim>
double min_distance(const std::vector<Vec<Dim>>& points) {
  double best = 1e300;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      best = std::min(best, (points[i] - points[j]).norm());
  return best;
}

template <int Dim>
void check_quasi_random(int per_cell) {
  const double h = 0.2;
  const auto g = grid<Dim>(h, 5);
  Box<Dim> box{g.origin, g.upper()};
  const SeedingPattern pattern{SeedingPattern::Kind::quasi_random, 2, per_cell};
  const auto a = seed_region(box, g, pattern);
  const auto b = seed_region(box, g, pattern);
  ASSERT_EQ(a.size(),
            static_cast<std::size_t>(per_cell) * static_cast<std::size_t>(std::pow(5, Dim)));
  EXPECT_EQ(a.positions, b.positions);  // deterministic
  EXPECT_NEAR(a.total_volume(), box.volume(), 1e-12);
  // each cell holds exactly per_cell points, strictly inside it
  std::vector<int> count(static_cast<std::size_t>(std::pow(5, Dim)), 0);
  for (const auto& x : a.positions) {
    std::size_t flat = 0;
    for (int d = Dim - 1; d >= 0; --d) {
      const double xi = (x[d] - g.origin[d]) / h;
      EXPECT_GT(xi - std::floor(xi), 0.0);
      flat = flat * 5 + static_cast<std::size_t>(std::floor(xi));
    }
    ++count[flat];
  }
  for (int c : count) EXPECT_EQ(c, per_cell);
  // well spread, also across cell faces: R_d keeps min distance above
  // 0.5 h / n^(1/Dim) for these counts
  const double bound = 0.5 * h / std::pow(per_cell, 1.0 / Dim);
  const double measured = min_distance<Dim>(a.positions);
  std::printf("R_%d, %d per cell: min distance %.4f h (bound %.4f h)\n", Dim, per_cell,
              measured / h, bound / h);
  EXPECT_GT(measured, bound);
}

TEST(Seeding, QuasiRandomIsDeterministicInsideItsCellsAndWellSpread) {
  for (int n : {1, 3, 4, 5, 9, 16}) check_quasi_random<2>(n);
  for (int n : {2, 5, 8}) check_quasi_random<3>(n);
}

TEST(Seeding, RejectsBadCounts) {
  const auto g = grid<2>(0.1, 10);
  const Box<2> box{g.origin, g.upper()};
  EXPECT_THROW(seed_region(box, g, SeedingPattern{SeedingPattern::Kind::regular, 0, 0}),
               cosim::InputError);
}

}  // namespace
}  // namespace mpm
