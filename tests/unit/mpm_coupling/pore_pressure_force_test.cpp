// The pore pressure acts on the solid as -phi_s grad p (Tran et al., MPMICE, eq. 7).
#include "mpm/coupling/pore_pressure_force.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mpm/coupling/exchange_grid.hpp"
#include "particle_fixtures.hpp"

namespace mpm::coupling {
namespace {

ExchangeGrid<2> column_grid() {
  const Grid<2> g = make_grid<2>(Vec<2>::Zero(), Vec<2>(0.1, 0.1), {10, 20}, ShapeKind::linear);
  return ExchangeGrid<2>::covering(g, 1);
}

std::vector<double> cell_field(const ExchangeGrid<2>& grid,
                               const std::function<double(const Vec<2>&)>& f) {
  std::vector<double> v(grid.size());
  for (int j = 0; j < grid.cells[1]; ++j)
    for (int i = 0; i < grid.cells[0]; ++i) v[grid.flat({i, j})] = f(grid.centre({i, j}));
  return v;
}

TEST(MpmCouplingPorePressure, ConstantPressureGivesNoForceAndIsTheParticlePressure) {
  const auto grid = column_grid();
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 1.2), 0.05, 0.4, 2650.0, 0);
  const auto roles = testing::porous_roles();
  std::vector<Vec<2>> force;
  const Vec<2> total = pore_pressure_force(
      grid, cell_field(grid, [](const Vec<2>&) { return 2.5e5; }), particles, roles, force);
  double worst = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    worst = std::max(worst, force[p].norm());
    EXPECT_NEAR(particles.pore_pressure[p], 2.5e5, 1e-9);
  }
  std::printf("  largest particle force %.2e N under a constant 2.5e5 Pa (tol 1e-9)\n", worst);
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(total.norm(), 1e-9);
}

TEST(MpmCouplingPorePressure, HydrostaticPressureGivesTheBuoyancyOfTheSolidVolume) {
  const auto grid = column_grid();
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 1.2), 0.05, 0.4, 2650.0, 0);
  testing::add_block<2>(particles, Vec<2>(0.2, 1.2), Vec<2>(0.6, 1.4), 0.05, 0.0, 2400.0,
                        1);  // impermeable block
  testing::add_block<2>(particles, Vec<2>(0.0, 1.8), Vec<2>(1.0, 2.0), 0.05, 0.3, 2650.0,
                        2);  // in the top half cells
  auto roles = testing::porous_roles(3);
  roles[1].porous = false;
  const double rho_w = 1000.0, g = 9.81, surface = 2.0;
  std::vector<Vec<2>> force;
  const Vec<2> total = pore_pressure_force(
      grid, cell_field(grid, [&](const Vec<2>& x) { return rho_w * g * (surface - x[1]); }),
      particles, roles, force);
  double solid_volume = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    solid_volume += (1.0 - particles.porosity[p]) * particles.volume[p];
    const double expected =
        roles[particles.body[p]].porous ? rho_w * g * (surface - particles.position[p][1]) : 0.0;
    EXPECT_NEAR(particles.pore_pressure[p], expected, 1e-8);
  }
  const double buoyancy = rho_w * g * solid_volume;
  const double error = std::abs(total[1] - buoyancy) / buoyancy;
  std::printf(
      "  buoyancy %.9g N vs rho_w g sum (1-n) V = %.9g N: relative error %.2e (tol 1e-12)\n",
      total[1], buoyancy, error);
  EXPECT_LT(error, 1e-12);
  EXPECT_LT(std::abs(total[0]), 1e-12 * buoyancy);
}

TEST(MpmCouplingPorePressure, LinearPressureGivesMinusSolidVolumeTimesGradientPerParticle) {
  const auto grid = column_grid();
  auto particles = testing::random_particles<2>(300, Vec<2>::Zero(), Vec<2>(1.0, 2.0), 11);
  const auto roles = testing::porous_roles();
  const Vec<2> gradient(-3.0e3, 7.0e3);
  std::vector<Vec<2>> force;
  const Vec<2> total = pore_pressure_force(
      grid, cell_field(grid, [&](const Vec<2>& x) { return 1e5 + gradient.dot(x); }), particles,
      roles, force);
  Vec<2> expected = Vec<2>::Zero();
  double worst = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const Vec<2> f = -(1.0 - particles.porosity[p]) * particles.volume[p] * gradient;
    expected += f;
    worst = std::max(worst, (force[p] - f).norm() / f.norm());
  }
  const double error = (total - expected).norm() / expected.norm();
  std::printf("  total relative error %.2e, worst particle %.2e (tol 1e-12)\n", error, worst);
  EXPECT_LT(error, 1e-12);
  EXPECT_LT(worst, 1e-12);
}

TEST(MpmCouplingPorePressure, RigidBodiesTakeNoForce) {
  const auto grid = column_grid();
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.2), 0.05, 0.0, 7800.0, 0);
  std::vector<BodyRole> roles(1);
  roles[0].rigid = roles[0].held = true;
  std::vector<Vec<2>> force;
  const Vec<2> total = pore_pressure_force(
      grid, cell_field(grid, [](const Vec<2>& x) { return 1e4 * (2.0 - x[1]); }), particles, roles,
      force);
  EXPECT_EQ(total.norm(), 0.0);
}

}  // namespace
}  // namespace mpm::coupling
