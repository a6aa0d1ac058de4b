// The exchange impulse is split over the particles by mass and applied in
// full over a window.
#include "mpm/coupling/momentum_exchange_increment.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mock_channel.hpp"
#include "mpm/coupling/exchange_grid.hpp"
#include "mpm/coupling/field_names.hpp"
#include "particle_fixtures.hpp"

namespace mpm::coupling {
namespace {

TEST(MpmCouplingImpulse, SplitOverParticlesConservesEachCellsImpulse) {
  const Grid<3> g =
      make_grid<3>(Vec<3>::Zero(), Vec<3>::Constant(0.25), {4, 4, 4}, ShapeKind::linear);
  const auto grid = ExchangeGrid<3>::covering(g, 1);
  // Particles everywhere, so every cell holds solid.
  auto particles = testing::random_particles<3>(2000, Vec<3>::Zero(), Vec<3>::Ones(), 5);
  const auto roles = testing::porous_roles();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> impulse(grid.size() * 3);
  for (double& j : impulse) j = u(rng);
  std::vector<Vec<3>> particle_impulse;
  const auto split = split_impulse(grid, impulse, particles, roles, particle_impulse);
  Vec<3> sum = Vec<3>::Zero();
  for (const auto& j : particle_impulse) sum += j;
  const double error = (sum - split.received).norm() / split.received.norm();
  std::printf("  sum over particles vs cells: relative error %.2e (tol 1e-12)\n", error);
  EXPECT_LT(error, 1e-12);
  EXPECT_EQ(split.absorbed.norm(), 0.0);
  EXPECT_LT((split.applied - sum).norm(), 1e-15 * sum.norm() + 1e-300);
}

TEST(MpmCouplingImpulse, CellsWithOnlyRigidSolidAbsorbTheirImpulseAndEmptyCellsPassItOn) {
  const Grid<2> g = make_grid<2>(Vec<2>::Zero(), Vec<2>::Constant(0.25), {4, 4}, ShapeKind::linear);
  const auto grid = ExchangeGrid<2>::covering(g, 1);
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.5), 0.125, 0.0, 7800.0,
                        0);  // rigid floor
  testing::add_block<2>(particles, Vec<2>(0.0, 0.5), Vec<2>(0.5, 0.75), 0.125, 0.4, 2650.0,
                        1);  // soil, left half
  auto roles = testing::porous_roles(2);
  roles[0].rigid = roles[0].held = true;
  std::vector<double> impulse(grid.size() * 2, 0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      impulse[grid.flat({i, j}) * 2 + 1] = 1.0;  // 1 kg m/s up in every cell
  std::vector<Vec<2>> particle_impulse;
  const auto split = split_impulse(grid, impulse, particles, roles, particle_impulse);
  for (std::size_t p = 0; p < particles.size(); ++p)
    if (particles.body[p] == 0) {
      EXPECT_EQ(particle_impulse[p].norm(), 0.0);
    }
  // The particles' domains fill exactly their blocks: rows 0-1 hold only the
  // floor's weight, and the empty cells (3, 2) and (3, 3) have no soil
  // beside them: absorbed. The soil's cells (0..1, 2) keep theirs and the
  // empty (2, 2), (0..2, 3) pass theirs to the soil beside them.
  EXPECT_NEAR(split.received[1], 16.0, 1e-12);
  EXPECT_NEAR(split.absorbed[1], 8.0 + 2.0, 1e-12);
  EXPECT_NEAR(split.applied[1], 6.0, 1e-12);
  Vec<2> sum = Vec<2>::Zero();
  for (const auto& j : particle_impulse) sum += j;
  EXPECT_LT((sum - split.applied).norm(), 1e-12);
}

TEST(MpmCouplingImpulse, StepSharesOverAWindowAddUpToTheReceivedImpulse) {
  const Grid<2> g =
      make_grid<2>(Vec<2>::Zero(), Vec<2>::Constant(0.1), {10, 10}, ShapeKind::linear);
  const auto grid = ExchangeGrid<2>::covering(g, 1);
  auto particles = testing::random_particles<2>(800, Vec<2>::Zero(), Vec<2>::Ones(), 21);
  const auto roles = testing::porous_roles();
  testing::MockChannel channel;
  channel.window = 1e-3;
  channel.declare_mesh({names::exchange_mesh, grid.mesh()});
  cosim::FieldSpec spec{.name = names::impulse,
                        .mesh = names::exchange_mesh,
                        .components = 2,
                        .unit = "kg m/s",
                        .quantity = cosim::Quantity::extensive,
                        .time = cosim::TimeTreatment::integral};
  channel.declare_read(spec, 0.0);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> window_impulse(grid.size() * 2);
  for (double& j : window_impulse) j = u(rng);
  channel.set(names::impulse, window_impulse);
  Vec<2> received = Vec<2>::Zero();
  for (std::size_t c = 0; c < grid.size(); ++c)
    received += Vec<2>(window_impulse[2 * c], window_impulse[2 * c + 1]);

  Vec<2> applied = Vec<2>::Zero();
  std::vector<double> step(grid.size() * 2);
  std::vector<Vec<2>> particle_impulse;
  int steps = 0;
  while (channel.max_time_step() > 0.0 && steps < 1000) {
    const double dt = std::min(0.7e-4 * (1.0 + 0.3 * std::sin(steps)), channel.max_time_step());
    channel.read_increment(names::impulse, dt, step);
    split_impulse(grid, step, particles, roles, particle_impulse);
    for (const auto& j : particle_impulse) applied += j;
    for (std::size_t p = 0; p < particles.size(); ++p)
      particles.position[p][0] = std::fmod(particles.position[p][0] + 0.013, 1.0);
    const bool last = dt >= channel.max_time_step() - 1e-12;
    channel.advance(dt);
    ++steps;
    if (last) break;
  }
  const double error = (applied - received).norm() / received.norm();
  std::printf("  %d steps: applied over the window vs received: relative error %.2e (tol 1e-12)\n",
              steps, error);
  EXPECT_GT(steps, 5);
  EXPECT_LT(error, 1e-12);
}

TEST(MpmCouplingImpulse, PressureForceBySolidVolumeGivesTheRigidBedItsShare) {
  // One row of cells, each half filled by a non-porous rigid bed (bottom) and
  // half by sand of porosity 0.4 (top): phi_s = 0.5 + 0.5 x 0.6 = 0.8. The
  // fluid solver's pressure force -phi_s grad P V_c split by solid volume gives
  // the sand 0.3 / 0.8 of it (its own -(1 - n) V grad P) and the bed 0.5 / 0.8,
  // absorbed; split by mass the sand would take all of it.
  const Grid<2> g = make_grid<2>(Vec<2>::Zero(), Vec<2>::Constant(0.25), {4, 1}, ShapeKind::linear);
  const auto grid = ExchangeGrid<2>::covering(g, 1);
  Particles<2> particles;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.125), 0.125, 0.0, 8900.0, 0);
  testing::add_block<2>(particles, Vec<2>(0.0, 0.125), Vec<2>(1.0, 0.25), 0.125, 0.4, 2650.0, 1);
  auto roles = testing::porous_roles(2);
  roles[0].rigid = roles[0].held = true;
  roles[0].porous = false;
  std::vector<double> force(grid.size() * 2, 0.0);
  for (int i = 0; i < 4; ++i) force[grid.flat({i, 0}) * 2 + 1] = 0.8;  // N, upwards
  std::vector<Vec<2>> by_volume, by_mass;
  const auto split =
      split_impulse(grid, force, particles, roles, by_volume, SplitWeight::solid_volume);
  split_impulse(grid, force, particles, roles, by_mass);
  double sand_volume = 0.0, sand_force = 0.0, sand_by_mass = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (particles.body[p] == 0) {
      EXPECT_EQ(by_volume[p].norm(), 0.0);
      continue;
    }
    sand_volume += (1.0 - particles.porosity[p]) * particles.volume[p];
    sand_force += by_volume[p][1];
    sand_by_mass += by_mass[p][1];
    // Each sand point: 0.8 N per cell of 0.0625 m2 over the cell's solid
    // volume 0.8 x 0.0625: 16 N per m3 of its own solid.
    EXPECT_NEAR(by_volume[p][1], 16.0 * (1.0 - particles.porosity[p]) * particles.volume[p], 1e-12);
  }
  EXPECT_NEAR(sand_volume, 4 * 0.3 * 0.0625, 1e-12);
  EXPECT_NEAR(sand_force, 4 * 0.3, 1e-12);
  EXPECT_NEAR(split.absorbed[1], 4 * 0.5, 1e-12);
  EXPECT_NEAR(split.applied[1] + split.absorbed[1], split.received[1], 1e-12);
  EXPECT_NEAR(sand_by_mass, 4 * 0.8, 1e-12);
}

}  // namespace
}  // namespace mpm::coupling
