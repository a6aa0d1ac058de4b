#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "cosim/error.hpp"
#include "mapping/build_operator.hpp"
#include "mapping_test_support.hpp"

namespace cosim::mapping {
namespace {

using testing::max_column_sum_error;
using testing::max_row_sum_error;
using testing::random_values;
using testing::relative_difference;
using testing::sum;

constexpr Kernel kKernels[] = {Kernel::linear, Kernel::quadratic_bspline};
constexpr GridLocation kLocations[] = {GridLocation::cell, GridLocation::node};

UniformGrid unit_box_grid(int dim, GridLocation location, std::int64_t cells) {
  UniformGrid g;
  g.dim = dim;
  g.location = location;
  for (int d = 0; d < dim; ++d) {
    const auto u = static_cast<std::size_t>(d);
    g.cells[u] = cells;
    g.spacing[u] = 1.0 / static_cast<double>(cells);
  }
  return g;
}

// Particles uniformly in [lo, hi]^dim with random volumes.
PointCloud random_particles(int dim, std::size_t n, double lo, double hi, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(lo, hi);
  PointCloud cloud;
  cloud.dim = dim;
  for (std::size_t p = 0; p < n * static_cast<std::size_t>(dim); ++p)
    cloud.positions.push_back(u(rng));
  cloud.volumes = random_values(n, rng, 1e-4, 2e-4);
  return cloud;
}

TEST(KernelMap, ParticleToGridKeepsTheTotalIncludingNearAndBeyondTheBoundary) {
  std::mt19937_64 rng(42);
  for (int dim = 1; dim <= 3; ++dim) {
    double worst = 0.0;
    double worst_column = 0.0;
    for (const Kernel kernel : kKernels)
      for (const GridLocation location : kLocations) {
        // particles over [-0.3, 1.3]: inside, in the boundary cells and outside
        const Mesh particles{"particles", random_particles(dim, 2000, -0.3, 1.3, rng)};
        const Mesh grid{"grid", unit_box_grid(dim, location, 8)};
        const Operator op = build_operator(particles, grid, Constraint::conservative, {kernel});
        const auto mass = random_values(particles.size(), rng);
        worst = std::max(worst, relative_difference(sum(mass), sum(op.apply(mass))));
        worst_column = std::max(worst_column, max_column_sum_error(op.weights()));
        EXPECT_GT(op.fallback_source_count(), 0u);
      }
    std::printf(
        "%dD particles->grid conservative: max relative total error %.3e, column sums %.3e\n", dim,
        worst, worst_column);
    EXPECT_LE(worst, 1e-12);
    EXPECT_LE(worst_column, 1e-12);
  }
}

TEST(KernelMap, ParticleInTheBoundaryHalfCellKeepsItsAmount) {
  for (const Kernel kernel : kKernels) {
    const Mesh grid{"grid", unit_box_grid(1, GridLocation::cell, 10)};
    const Mesh one{"one", PointCloud{1, {0.01}, {0.001}}};  // left of the first cell centre
    const auto mapped = build_operator(one, grid, Constraint::conservative, {kernel})
                            .apply(std::vector<double>{2.5});
    std::printf("%s: boundary particle amount on grid %.17g of 2.5\n", to_string(kernel),
                sum(mapped));
    EXPECT_DOUBLE_EQ(sum(mapped), 2.5);
    EXPECT_GT(mapped[0], mapped[1]);
  }
}

double linear_field(const Vec3& x) {
  return -0.5 + 1.25 * x[0] + 3.0 * x[1] - 2.0 * x[2];
}

TEST(KernelMap, GridToParticlesReproducesALinearFieldInTheInterior) {
  std::mt19937_64 rng(9);
  for (const Kernel kernel : kKernels)
    for (int dim = 1; dim <= 3; ++dim) {
      double worst = 0.0;
      double worst_row = 0.0;
      for (const GridLocation location : kLocations) {
        const Mesh grid{"grid", unit_box_grid(dim, location, 10)};
        // at least 1.5 spacings from the first and last grid points
        const Mesh particles{"particles", random_particles(dim, 500, 0.2, 0.8, rng)};
        const Operator op = build_operator(grid, particles, Constraint::consistent, {kernel});
        std::vector<double> f(grid.size());
        for (std::size_t e = 0; e < f.size(); ++e) f[e] = linear_field(grid.position(e));
        const auto mapped = op.apply(f);
        for (std::size_t p = 0; p < mapped.size(); ++p)
          worst = std::max(worst, std::abs(mapped[p] - linear_field(particles.position(p))));
        worst_row = std::max(worst_row, max_row_sum_error(op.weights()));
      }
      std::printf("%s %dD grid->particles, linear field: max error %.3e, row sums %.3e\n",
                  to_string(kernel), dim, worst, worst_row);
      EXPECT_LE(worst, 1e-13);
      EXPECT_LE(worst_row, 1e-14);
    }
}

TEST(KernelMap, ParticlesToGridConsistentAveragesAndReportsEmptyNodes) {
  std::mt19937_64 rng(13);
  for (const Kernel kernel : kKernels) {
    const Mesh grid{"grid", unit_box_grid(2, GridLocation::node, 10)};
    // particles only in the lower left quarter: nodes beyond x or y = 0.65 see none
    const Mesh particles{"particles", random_particles(2, 3000, 0.0, 0.5, rng)};
    const Operator op = build_operator(particles, grid, Constraint::consistent, {kernel});
    const auto mapped = op.apply(std::vector<double>(particles.size(), 7.0));
    std::vector<bool> empty(grid.size(), false);
    for (const std::size_t t : op.empty_target_indices()) empty[t] = true;
    double worst = 0.0;
    for (std::size_t t = 0; t < grid.size(); ++t) {
      worst = std::max(worst, std::abs(mapped[t] - (empty[t] ? 0.0 : 7.0)));
      const Vec3 x = grid.position(t);
      if (x[0] > 0.65 || x[1] > 0.65) {
        EXPECT_TRUE(empty[t]);
      }
      if (x[0] < 0.45 && x[1] < 0.45) {
        EXPECT_FALSE(empty[t]);
      }
    }
    std::printf(
        "%s particles->grid consistent: %zu empty of %zu nodes, relative constant error %.3e\n",
        to_string(kernel), op.empty_target_count(), grid.size(), worst / 7.0);
    EXPECT_LE(worst / 7.0, 1e-14);
  }
}

TEST(KernelMap, ConsistentParticlesToGridIsTheVolumeWeightedKernelAverage) {
  const Mesh grid{"grid", unit_box_grid(1, GridLocation::node, 2)};  // nodes 0, 0.5, 1
  const Mesh particles{"particles", PointCloud{1, {0.25, 0.4}, {1.0, 3.0}}};
  const auto mapped =
      build_operator(particles, grid, Constraint::consistent).apply(std::vector<double>{1.0, 2.0});
  // node 0.5: tent weights 0.5 and 0.8, times volumes 1 and 3
  EXPECT_NEAR(mapped[1], (0.5 * 1.0 * 1.0 + 0.8 * 3.0 * 2.0) / (0.5 * 1.0 + 0.8 * 3.0), 1e-15);
  EXPECT_NEAR(mapped[0], (0.5 * 1.0 * 1.0 + 0.2 * 3.0 * 2.0) / (0.5 * 1.0 + 0.2 * 3.0), 1e-15);
  EXPECT_EQ(mapped[2], 0.0);
  EXPECT_EQ(build_operator(particles, grid, Constraint::consistent).empty_target_count(), 1u);
}

TEST(KernelMap, GridToParticlesConservativeKeepsEveryGridAmount) {
  std::mt19937_64 rng(21);
  double worst = 0.0;
  for (int dim = 1; dim <= 3; ++dim)
    for (const Kernel kernel : kKernels) {
      const Mesh grid{"grid", unit_box_grid(dim, GridLocation::cell, 6)};
      // a blob in one corner: most grid cells have no particle near them
      const Mesh particles{"particles", random_particles(dim, 300, 0.1, 0.4, rng)};
      const Operator op = build_operator(grid, particles, Constraint::conservative, {kernel});
      EXPECT_GT(op.fallback_source_count(), 0u);
      const auto impulse = random_values(grid.size(), rng);
      worst = std::max(worst, relative_difference(sum(impulse), sum(op.apply(impulse))));
      const Operator reverse = build_operator(particles, grid, Constraint::consistent, {kernel});
      EXPECT_EQ(op.fallback_source_count(), reverse.empty_target_count());
    }
  std::printf("grid->particles conservative: max relative total error %.3e\n", worst);
  EXPECT_LE(worst, 1e-12);
}

TEST(KernelMap, ParticleRoundTripKeepsTheTotal) {
  std::mt19937_64 rng(8);
  double worst = 0.0;
  for (const Kernel kernel : kKernels) {
    const Mesh grid{"grid", unit_box_grid(3, GridLocation::node, 7)};
    const Mesh particles{"particles", random_particles(3, 4000, -0.1, 1.1, rng)};
    const auto mass = random_values(particles.size(), rng);
    const auto on_grid =
        build_operator(particles, grid, Constraint::conservative, {kernel}).apply(mass);
    const auto back =
        build_operator(grid, particles, Constraint::conservative, {kernel}).apply(on_grid);
    worst = std::max(worst, relative_difference(sum(mass), sum(back)));
  }
  std::printf("particles->grid->particles conservative: relative total change %.3e\n", worst);
  EXPECT_LE(worst, 1e-12);
}

TEST(KernelMap, CellCloudBehavesLikeParticles) {
  std::mt19937_64 rng(4);
  const PointCloud points = random_particles(2, 1000, 0.0, 1.0, rng);
  const Mesh cells{"openfoam", CellCloud{2, points.positions, points.volumes}};
  const Mesh as_points{"points", points};
  const Mesh grid{"grid", unit_box_grid(2, GridLocation::cell, 12)};
  for (const Constraint c : {Constraint::conservative, Constraint::consistent}) {
    const Weights a = build_operator(cells, grid, c, {Kernel::quadratic_bspline}).weights();
    const Weights b = build_operator(as_points, grid, c, {Kernel::quadratic_bspline}).weights();
    EXPECT_EQ(Weights(a - b).norm(), 0.0);
    const auto amount = random_values(cells.size(), rng);
    const auto mapped = build_operator(cells, grid, Constraint::conservative).apply(amount);
    EXPECT_LE(relative_difference(sum(amount), sum(mapped)), 1e-12);
  }
  const Operator to_cells = build_operator(grid, cells, Constraint::consistent);
  const auto constant = to_cells.apply(std::vector<double>(grid.size(), 0.4));
  for (const double v : constant) EXPECT_NEAR(v, 0.4, 1e-15);
}

// A participant's cloud and the exchange on that same cloud (a user's
// OpenFOAM mesh as the momentum exchange's mesh): values pass unchanged,
// so amounts are kept exactly; a cloud that differs is still refused.
TEST(KernelMap, ACloudMapsToItselfAsTheIdentity) {
  std::mt19937_64 rng(5);
  const PointCloud points = random_particles(2, 300, 0.0, 1.0, rng);
  const Mesh cells{"openfoam_cells", CellCloud{2, points.positions, points.volumes}};
  const Mesh same{"openfoam_cells", CellCloud{2, points.positions, points.volumes}};
  for (const Constraint c : {Constraint::conservative, Constraint::consistent}) {
    const Operator map = build_operator(cells, same, c);
    const auto values = random_values(2 * cells.size(), rng);
    EXPECT_EQ(map.apply(values, 2), values);
  }
  PointCloud moved = points;
  moved.positions[0] += 1e-3;
  const Mesh other{"other", CellCloud{2, moved.positions, moved.volumes}};
  EXPECT_THROW(build_operator(cells, other, Constraint::consistent), cosim::InputError);
}

TEST(KernelMap, ConservativeParticleToGridIsTheTransposeOfGridToParticleInterpolation) {
  std::mt19937_64 rng(17);
  const Mesh grid{"grid", unit_box_grid(3, GridLocation::cell, 5)};
  const Mesh particles{"particles", random_particles(3, 700, -0.2, 1.2, rng)};
  const Weights c = build_operator(particles, grid, Constraint::conservative).weights();
  const Weights i = build_operator(grid, particles, Constraint::consistent).weights();
  const double norm = Weights(c - Weights(i.transpose())).norm();
  std::printf("||P->G conservative - (G->P consistent)^T|| = %.3e\n", norm);
  EXPECT_EQ(norm, 0.0);
}

}  // namespace
}  // namespace cosim::mapping
