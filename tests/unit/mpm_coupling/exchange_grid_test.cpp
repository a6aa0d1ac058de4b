// The exchange grid's particle -> cell map conserves mass, momentum and solid
// volume; its cell -> point interpolation is exact for linear fields.
#include "mpm/coupling/exchange_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mpm/coupling/porous_fields_writer.hpp"
#include "particle_fixtures.hpp"

namespace mpm::coupling {
namespace {

template <int Dim>
ExchangeGrid<Dim> unit_square_grid(int cells_per_direction, int factor) {
  std::array<int, Dim> cells{};
  cells.fill(cells_per_direction);
  const Grid<Dim> g = make_grid<Dim>(
      Vec<Dim>::Zero(), Vec<Dim>::Constant(1.0 / cells_per_direction), cells, ShapeKind::linear);
  return ExchangeGrid<Dim>::covering(g, factor);
}

template <int Dim>
void expect_conservative(int cells, int factor) {
  const auto grid = unit_square_grid<Dim>(cells, factor);
  auto particles = testing::random_particles<Dim>(500, Vec<Dim>::Zero(), Vec<Dim>::Ones(),
                                                  7u + static_cast<unsigned>(factor));
  const auto roles = testing::porous_roles();
  const std::vector<std::uint8_t> none(particles.size(), 0);
  const PorousFields f = porous_fields(grid, particles, roles, none, 1e30);

  double mass = 0.0, solid_volume = 0.0;
  Vec<Dim> momentum = Vec<Dim>::Zero();
  for (std::size_t p = 0; p < particles.size(); ++p) {
    mass += particles.mass[p];
    solid_volume += (1.0 - particles.porosity[p]) * particles.volume[p];
    momentum += particles.mass[p] * particles.velocity[p];
  }
  double cell_mass = 0.0, cell_solid_volume = 0.0;
  Vec<Dim> cell_momentum = Vec<Dim>::Zero();
  const double vc = grid.cell_volume();
  for (std::size_t c = 0; c < grid.size(); ++c) {
    cell_mass += f.solid_bulk_density[c] * vc;
    cell_solid_volume += f.solid_fraction[c] * vc;
    for (int k = 0; k < Dim; ++k)
      cell_momentum[k] +=
          f.solid_bulk_density[c] * vc * f.solid_velocity[c * Dim + static_cast<std::size_t>(k)];
  }
  EXPECT_EQ(f.capped_cells, 0u);
  const double mass_error = std::abs(cell_mass - mass) / mass;
  const double volume_error = std::abs(cell_solid_volume - solid_volume) / solid_volume;
  const double momentum_error = (cell_momentum - momentum).norm() / momentum.norm();
  std::printf(
      "  %dD, %d cells, factor %d: relative errors mass %.2e, solid volume %.2e, momentum %.2e "
      "(tol 1e-12)\n",
      Dim, cells, factor, mass_error, volume_error, momentum_error);
  EXPECT_LT(mass_error, 1e-12);
  EXPECT_LT(volume_error, 1e-12);
  EXPECT_LT(momentum_error, 1e-12);
}

TEST(MpmCouplingExchangeGrid, ParticleToCellMapConservesMassSolidVolumeAndMomentum2D) {
  expect_conservative<2>(8, 1);
  expect_conservative<2>(8, 3);  // 3 exchange cells per direction, the last one past the grid
}

TEST(MpmCouplingExchangeGrid, ParticleToCellMapConservesMassSolidVolumeAndMomentum3D) {
  expect_conservative<3>(4, 1);
  expect_conservative<3>(4, 2);
}

TEST(MpmCouplingExchangeGrid, CoarserFactorCoversTheGrid) {
  const Grid<2> g = make_grid<2>(Vec<2>(1.0, -2.0), Vec<2>(0.5, 0.25), {5, 8}, ShapeKind::gimp);
  const auto e = ExchangeGrid<2>::covering(g, 2);
  EXPECT_EQ(e.cells[0], 3);
  EXPECT_EQ(e.cells[1], 4);
  EXPECT_DOUBLE_EQ(e.spacing[0], 1.0);
  EXPECT_DOUBLE_EQ(e.spacing[1], 0.5);
  const cosim::UniformGrid m = e.mesh();
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.location, cosim::GridLocation::cell);
  EXPECT_EQ(m.size(), 12u);
  EXPECT_DOUBLE_EQ(m.origin[1], -2.0);
  // Same flat order as the coupler's mesh: x fastest.
  EXPECT_EQ(e.flat({2, 1}), m.flat(2, 1));
}

template <int Dim>
void expect_linear_exact() {
  const auto grid = unit_square_grid<Dim>(5, 1);
  Vec<Dim> slope;
  for (int k = 0; k < Dim; ++k) slope[k] = 1.5 - 2.0 * k;
  const double offset = 3.0;
  std::vector<double> p(grid.size());
  for (std::size_t c = 0; c < grid.size(); ++c) {
    std::array<int, Dim> index{};
    std::size_t rest = c;
    for (int k = 0; k < Dim; ++k) {
      index[static_cast<std::size_t>(k)] = static_cast<int>(rest % 5);
      rest /= 5;
    }
    p[c] = offset + slope.dot(grid.centre(index));
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst_value = 0.0, worst_gradient = 0.0, worst_sum = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    Vec<Dim> x;
    for (int k = 0; k < Dim; ++k) x[k] = u(rng);
    if (trial < 2)
      x.setConstant(trial == 0 ? 0.0 : 1.0);  // the corners, in the extrapolated half cells
    double value = 0.0, weights = 0.0;
    Vec<Dim> gradient = Vec<Dim>::Zero();
    grid.for_each_consistent(x, [&](std::size_t c, double w, const Vec<Dim>& dw) {
      value += w * p[c];
      gradient += dw * p[c];
      weights += w;
    });
    worst_value = std::max(worst_value, std::abs(value - (offset + slope.dot(x))));
    worst_gradient = std::max(worst_gradient, (gradient - slope).norm());
    worst_sum = std::max(worst_sum, std::abs(weights - 1.0));
  }
  std::printf("  %dD: max error value %.2e, gradient %.2e, weight sum %.2e (tol 1e-12)\n", Dim,
              worst_value, worst_gradient, worst_sum);
  EXPECT_LT(worst_value, 1e-12);
  EXPECT_LT(worst_gradient, 1e-12);
  EXPECT_LT(worst_sum, 1e-12);
}

TEST(MpmCouplingExchangeGrid, CellToPointInterpolationIsExactForLinearFieldsUpToTheFaces) {
  expect_linear_exact<2>();
  expect_linear_exact<3>();
}

TEST(MpmCouplingExchangeGrid, ConservativeWeightsAreNonNegativePartitionOfUnity) {
  const auto grid = unit_square_grid<2>(4, 1);
  for (const Vec<2>& x :
       {Vec<2>(0.0, 0.0), Vec<2>(0.01, 0.99), Vec<2>(0.5, 0.3), Vec<2>(1.0, 1.0)}) {
    double sum = 0.0;
    grid.for_each_conservative(x, [&](std::size_t, double w) {
      EXPECT_GE(w, 0.0);
      sum += w;
    });
    EXPECT_NEAR(sum, 1.0, 1e-15);
  }
}

TEST(MpmCouplingExchangeGrid, DomainWeightsAreTheOverlapOfTheParticleWithEachCell) {
  const auto grid = unit_square_grid<2>(4, 1);
  // A domain [0.2, 0.3] x [0.45, 0.55] over cells of 0.25: half in each of
  // two cells per direction.
  std::vector<double> weight(grid.size(), 0.0);
  grid.for_each_conservative(Vec<2>(0.25, 0.5), Vec<2>(0.05, 0.05),
                             [&](std::size_t c, double w) { weight[c] += w; });
  EXPECT_NEAR(weight[grid.flat({0, 1})], 0.25, 1e-15);
  EXPECT_NEAR(weight[grid.flat({1, 1})], 0.25, 1e-15);
  EXPECT_NEAR(weight[grid.flat({0, 2})], 0.25, 1e-15);
  EXPECT_NEAR(weight[grid.flat({1, 2})], 0.25, 1e-15);
  // Past the grid's side the domain's share goes to the cell at the face.
  std::fill(weight.begin(), weight.end(), 0.0);
  grid.for_each_conservative(Vec<2>(0.98, 0.1), Vec<2>(0.05, 0.05),
                             [&](std::size_t c, double w) { weight[c] += w; });
  EXPECT_NEAR(weight[grid.flat({3, 0})], 1.0, 1e-15);
  // A point without a domain takes the linear weights.
  double sum = 0.0;
  int cells = 0;
  grid.for_each_conservative(Vec<2>(0.3, 0.3), Vec<2>::Zero(), [&](std::size_t, double w) {
    sum += w;
    ++cells;
  });
  EXPECT_NEAR(sum, 1.0, 1e-15);
  EXPECT_EQ(cells, 4);
}

TEST(MpmCouplingExchangeGrid, ABoxBodyFillsExactlyTheCellsItCovers) {
  // Two points per cell and direction: with linear weights a quarter of the
  // surface row's volume would land in the empty row above.
  const auto grid = unit_square_grid<2>(4, 1);
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.5), 0.125, 0.4, 2650.0, 0);
  const auto roles = testing::porous_roles(1);
  const std::vector<std::uint8_t> held(particles.size(), 0);
  const PorousFields f = porous_fields(grid, particles, roles, held, 1e30);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(f.solid_fraction[grid.flat({i, 1})], 0.6, 1e-12);
    EXPECT_EQ(f.solid_fraction[grid.flat({i, 2})], 0.0);
  }
}

TEST(MpmCouplingExchangeGrid, HeldSolidIsWrittenWithAnEffectivelyInfiniteBulkDensity) {
  const auto grid = unit_square_grid<2>(4, 1);
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.25), 0.125, 0.4, 2650.0,
                        0);  // bottom row: held
  testing::add_block<2>(particles, Vec<2>(0.0, 0.25), Vec<2>(1.0, 1.0), 0.125, 0.4, 2650.0, 1);
  std::vector<BodyRole> roles = testing::porous_roles(2);
  roles[0].held = true;
  std::vector<std::uint8_t> held(particles.size(), 0);
  for (std::size_t p = 0; p < particles.size(); ++p) held[p] = roles[particles.body[p]].held;
  const PorousFields f = porous_fields(grid, particles, roles, held, 1e30);
  const double rho_bar = 2650.0 * 0.6;
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(f.held[grid.flat({i, 0})], 1);
    EXPECT_NEAR(f.solid_bulk_density[grid.flat({i, 0})], 1e30 * rho_bar, 1e-12 * 1e30 * rho_bar);
    EXPECT_EQ(f.held[grid.flat({i, 1})], 0);
    EXPECT_NEAR(f.solid_bulk_density[grid.flat({i, 1})], rho_bar, 1e-9);
    EXPECT_NEAR(f.solid_fraction[grid.flat({i, 1})], 0.6, 1e-12);
    EXPECT_NEAR(f.permeability[grid.flat({i, 1})], 1e-10, 1e-22);
    EXPECT_NEAR(f.solid_bulk_density[grid.flat({i, 3})], rho_bar, 1e-9);
  }
}

TEST(MpmCouplingExchangeGrid, HeldCellMovesWithItsHeldSolidAlone) {
  // A held body at rest fills the bottom row; a deformable one slides over it at 2 m/s with points
  // whose domains reach 2 cm down into the held cells. The held cells keep the held body's velocity
  // (0), the cells above take the sliding body's; the solid fraction counts both.
  const auto grid = unit_square_grid<2>(4, 1);
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.25), 0.125, 0.0, 8900.0, 0);
  testing::add_block<2>(particles, Vec<2>(0.0, 0.25), Vec<2>(1.0, 0.5), 0.125, 0.4, 2650.0, 1);
  std::vector<BodyRole> roles = testing::porous_roles(2);
  roles[0].held = roles[0].rigid = true;
  roles[0].porous = false;
  std::vector<std::uint8_t> held(particles.size(), 0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    held[p] = roles[particles.body[p]].held;
    if (particles.body[p] == 1) {
      particles.velocity[p] = Vec<2>(2.0, 0.0);
      particles.position[p][1] -= 0.02;
    }
  }
  const PorousFields f = porous_fields(grid, particles, roles, held, 1e30);
  for (int i = 0; i < 4; ++i) {
    const std::size_t bottom = grid.flat({i, 0}), above = grid.flat({i, 1});
    EXPECT_EQ(f.held[bottom], 1);
    EXPECT_EQ(f.solid_velocity[bottom * 2], 0.0);
    EXPECT_EQ(f.solid_velocity[bottom * 2 + 1], 0.0);
    EXPECT_EQ(f.held[above], 0);
    EXPECT_NEAR(f.solid_velocity[above * 2], 2.0, 1e-12);
    // The sand's domains overfill the held cells by 0.02 / 0.25 of a row: handed back to the row
    // above, which they left as short, so each row holds its own solid again (to the 0.1 %
    // overfill the spreading leaves).
    EXPECT_EQ(f.solid_fraction[bottom], 1.0);
    EXPECT_NEAR(f.solid_fraction[above], 0.6, 1e-3);
    EXPECT_NEAR(f.solid_bulk_density[above], 0.6 * 2650.0, 2.0);
  }
  EXPECT_EQ(f.overfilled_cells, 4u);
  EXPECT_EQ(f.capped_cells, 0u);
}

TEST(MpmCouplingExchangeGrid, ClusteredPointsHandTheirExcessToTheCellTheyLeftShort) {
  // A row of two cells of 0.4-porous sand, four points' worth of domain each: six points have
  // drifted into the left cell (at 1 m/s), two remain in the right (at 3 m/s). The left cell's
  // domains cover 1.5 cells, its solid fraction would be 0.9 where the sand's is 0.6; the spreading
  // hands a third of its sums to the right cell, conserving solid volume, mass and momentum.
  const auto grid = unit_square_grid<2>(4, 1);
  const double h = 0.25;
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(h, h), h / 2.0, 0.4, 2650.0, 0);
  testing::add_block<2>(particles, Vec<2>(h, 0.0), Vec<2>(2.0 * h, h), h / 2.0, 0.4, 2650.0, 0);
  for (std::size_t p = 0; p < 2; ++p) {  // two of the right cell's points drifted into the left one
    particles.position[p + 4][0] -= h / 2.0 + 0.01;
    particles.position[p + 4][1] += 0.01;
  }
  for (std::size_t p = 0; p < particles.size(); ++p)
    particles.velocity[p] = Vec<2>(p < 6 ? 1.0 : 3.0, 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p)
    particles.half_length[p] = Vec<2>::Constant(h / 4.0 - 1e-6);
  const std::size_t left = grid.flat({0, 0}), right = grid.flat({1, 0});
  const PorousFields f = porous_fields(grid, particles, testing::porous_roles(1),
                                       std::vector<std::uint8_t>(particles.size(), 0), 1e30);
  EXPECT_EQ(f.overfilled_cells, 1u);
  EXPECT_EQ(f.capped_cells, 0u);
  const double point_mass = particles.mass[0];
  const double cell_volume = grid.cell_volume();
  std::printf("  solid fraction left %.6f right %.6f (sand 0.6)\n", f.solid_fraction[left],
              f.solid_fraction[right]);
  // The right cell accepts its room times the share of it its own points fill: the excess moves
  // over the sweeps, to the 0.1 % overfill the spreading leaves.
  EXPECT_NEAR(f.solid_fraction[left], 0.6, 2e-3);
  EXPECT_NEAR(f.solid_fraction[right], 0.6, 2e-3);
  EXPECT_NEAR((f.solid_fraction[left] + f.solid_fraction[right]) * cell_volume,
              8 * 0.6 * cell_volume / 4.0, 1e-12);
  EXPECT_NEAR((f.solid_bulk_density[left] + f.solid_bulk_density[right]) * cell_volume,
              8 * point_mass, 1e-12);
  const double momentum = (f.solid_bulk_density[left] * f.solid_velocity[left * 2] +
                           f.solid_bulk_density[right] * f.solid_velocity[right * 2]) *
                          cell_volume;
  EXPECT_NEAR(momentum, (6 * 1.0 + 2 * 3.0) * point_mass, 1e-12);
  // The right cell's own two points at 3 m/s and the two points' worth it was handed at 1 m/s.
  EXPECT_NEAR(f.solid_velocity[right * 2], 2.0, 1e-2);
}

TEST(MpmCouplingExchangeGrid, ACellSharedByABedAndSlidingSandMovesWithTheSand) {
  // Each cell of the row: its lower half a rigid bed at rest, its upper half sand sliding at 2 m/s.
  // The bed's mass is the larger, but the sand fills 30 % of the cell: not held, and the cell takes
  // the sand's velocity (mass-weighted over both it would be 0.30 m/s); phi_s counts both. The
  // solids' volume flux is the sand's alone, 0.3 x 2 m/s (phi_s U_s would say 1.6).
  const auto grid = unit_square_grid<2>(4, 1);
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.125), 0.125, 0.0, 8900.0, 0);
  testing::add_block<2>(particles, Vec<2>(0.0, 0.125), Vec<2>(1.0, 0.25), 0.125, 0.4, 2650.0, 1);
  std::vector<BodyRole> roles = testing::porous_roles(2);
  roles[0].held = roles[0].rigid = true;
  roles[0].porous = false;
  std::vector<std::uint8_t> held(particles.size(), 0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    held[p] = roles[particles.body[p]].held;
    if (particles.body[p] == 1) particles.velocity[p] = Vec<2>(2.0, 0.0);
  }
  const PorousFields f = porous_fields(grid, particles, roles, held, 1e30);
  for (int i = 0; i < 4; ++i) {
    const std::size_t c = grid.flat({i, 0});
    EXPECT_EQ(f.held[c], 0);
    EXPECT_NEAR(f.solid_velocity[c * 2], 2.0, 1e-12);
    EXPECT_NEAR(f.solid_fraction[c], 0.8, 1e-12);
    EXPECT_NEAR(f.solid_volume_flux[c * 2], 0.6, 1e-12);
    EXPECT_NEAR(f.solid_volume_flux[c * 2 + 1], 0.0, 1e-12);
    EXPECT_NEAR(f.solid_bulk_density[c], 0.5 * 8900.0 + 0.5 * 0.6 * 2650.0, 1e-9);
  }
}

TEST(MpmCouplingExchangeGrid, ACellItsDomainsFillExactlyIsNotCountedAsCapped) {
  // A non-porous block, 8 x 8 points per cell: the solid fraction sums to 1 within round-off.
  const auto grid = unit_square_grid<2>(4, 1);
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 1.0), 0.25 / 8.0, 0.0, 7800.0, 0);
  const PorousFields f = porous_fields(grid, particles, testing::porous_roles(1),
                                       std::vector<std::uint8_t>(particles.size(), 0), 1e30);
  for (double phi : f.solid_fraction) EXPECT_NEAR(phi, 1.0, 1e-12);
  EXPECT_EQ(f.capped_cells, 0u);
}

}  // namespace
}  // namespace mpm::coupling
