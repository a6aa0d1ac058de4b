#include "mapping/bounded_redistribution.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "cosim/error.hpp"
#include "mapping/build_operator.hpp"
#include "mapping_test_support.hpp"

namespace cosim::mapping {
namespace {

double volume_total(const Mesh& mesh, const std::vector<double>& phi) {
  double total = 0.0;
  for (std::size_t e = 0; e < phi.size(); ++e) total += phi[e] * mesh.control_volume(e);
  return total;
}

std::pair<double, double> range(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {*lo, *hi};
}

// Solid fraction φ_s = (solid volume mapped conservatively) / control volume
// overshoots where particles crowd; redistribution keeps Σ φ V and the bounds.
TEST(BoundedRedistribution, SolidFractionFromCrowdedParticlesKeepsTotalAndBound) {
  std::mt19937_64 rng(99);
  const Mesh grid{"mpm_grid",
                  UniformGrid{2, {0, 0, 0}, {0.1, 0.1, 1}, {10, 10, 1}, GridLocation::node}};
  std::uniform_real_distribution<double> u(0.3, 0.5);
  PointCloud soil{2, {}, {}};
  for (int p = 0; p < 400; ++p) {
    soil.positions.push_back(u(rng));
    soil.positions.push_back(u(rng));
    soil.volumes.push_back(1.5e-4);  // 0.06 of solid in 0.04 of space: φ well above 1
  }
  const Mesh particles{"soil", soil};
  const auto solid_volume =
      build_operator(particles, grid, Constraint::conservative).apply(soil.volumes);
  std::vector<double> phi(grid.size());
  for (std::size_t e = 0; e < phi.size(); ++e) phi[e] = solid_volume[e] / grid.control_volume(e);
  const double before = volume_total(grid, phi);
  const double phi_max = 0.95;
  ASSERT_GT(range(phi).second, phi_max);

  std::vector<double> clipped = phi;
  for (double& v : clipped) v = std::min(v, phi_max);
  const double clipping_loss = std::abs(volume_total(grid, clipped) - before) / before;

  redistribute_to_bounds(grid, phi, 0.0, phi_max);
  const double error = std::abs(volume_total(grid, phi) - before) / before;
  const auto [lo, hi] = range(phi);
  std::printf(
      "solid fraction: max before %.3f; clipping loses %.3e of the total, redistribution "
      "%.3e; range after [%.3f, %.17g]\n",
      *std::max_element(solid_volume.begin(), solid_volume.end()) / 0.01, clipping_loss, error, lo,
      hi);
  EXPECT_GT(clipping_loss, 1e-2);
  EXPECT_LE(error, 1e-12);
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, phi_max);
}

TEST(BoundedRedistribution, SpreadsPastFullNeighboursOnA3DGrid) {
  const Mesh grid{"g", UniformGrid{3, {0, 0, 0}, {1, 0.5, 2}, {5, 6, 4}, GridLocation::cell}};
  std::vector<double> phi(grid.size(), 0.9);
  const auto& g = std::get<UniformGrid>(grid.geometry);
  phi[g.flat(2, 3, 2)] = 3.0;  // neighbours are nearly full: the excess travels two layers
  const double before = volume_total(grid, phi);
  redistribute_to_bounds(grid, phi, 0.0, 1.0);
  const auto [lo, hi] = range(phi);
  const double error = std::abs(volume_total(grid, phi) - before) / before;
  std::printf("3D spike: relative total error %.3e, range [%.17g, %.17g]\n", error, lo, hi);
  EXPECT_LE(error, 1e-12);
  EXPECT_LE(hi, 1.0);
  EXPECT_GE(lo, 0.0);
  EXPECT_DOUBLE_EQ(phi[0], 0.9);                // seven faces away from the spike: untouched
  EXPECT_DOUBLE_EQ(phi[g.flat(2, 3, 1)], 1.0);  // first layer: filled
}

TEST(BoundedRedistribution, RaisesValuesBelowTheLowerBound) {
  const Mesh line{"swe_line", NonUniformLine{{0.0, 0.1, 0.3, 0.35, 0.8, 1.0}}};
  std::vector<double> phi{0.5, -0.2, 0.4, 0.6, -0.05};
  const double before = volume_total(line, phi);
  redistribute_to_bounds(line, phi, 0.0, 1.0);
  const double error = std::abs(volume_total(line, phi) - before) / std::abs(before);
  std::printf("line deficits: relative total error %.3e\n", error);
  EXPECT_LE(error, 1e-12);
  for (const double v : phi) {
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
}

TEST(BoundedRedistribution, CloudsUseNearbyElementsAndKeepTheTotal) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CellCloud cells{3, {}, {}};
  for (int c = 0; c < 2000; ++c) {
    for (int d = 0; d < 3; ++d) cells.centres.push_back(u(rng));
    cells.volumes.push_back(5e-4 * (0.5 + u(rng)));
  }
  const Mesh cloud{"foam_cells", cells};
  std::vector<double> phi(cells.volumes.size());
  for (double& v : phi) v = 0.3 + 0.9 * u(rng);  // about a quarter above 1
  const double before = volume_total(cloud, phi);
  redistribute_to_bounds(cloud, phi, 0.0, 1.0);
  const auto [lo, hi] = range(phi);
  const double error = std::abs(volume_total(cloud, phi) - before) / before;
  std::printf("cell cloud: relative total error %.3e, range [%.3f, %.17g]\n", error, lo, hi);
  EXPECT_LE(error, 1e-12);
  EXPECT_LE(hi, 1.0);
  EXPECT_GE(lo, 0.0);
}

TEST(BoundedRedistribution, ThrowsWhenTheTotalCannotFit) {
  const Mesh grid{"g", UniformGrid{1, {0, 0, 0}, {1, 1, 1}, {4, 1, 1}, GridLocation::cell}};
  std::vector<double> phi{1.0, 1.0, 1.5, 0.6};  // 4.1 of room 4.0
  try {
    redistribute_to_bounds(grid, phi, 0.0, 1.0);
    FAIL() << "accepted a total above the bound";
  } catch (const NumericalError& e) {
    std::printf("overfull: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("cannot fit"), std::string::npos);
  }
  std::vector<double> wrong_size(3, 0.5);
  EXPECT_THROW(redistribute_to_bounds(grid, wrong_size, 0.0, 1.0), InputError);
  std::vector<double> fine(4, 0.5);
  EXPECT_THROW(redistribute_to_bounds(grid, fine, 1.0, 0.0), InputError);
}

}  // namespace
}  // namespace cosim::mapping
