// MpmCoupling on a real solver with a mock partner: declarations, the call
// order, and what reaches the particles over whole windows.
#include "mpm/coupling/mpm_coupling.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mock_channel.hpp"
#include "mpm/coupling/coupling_observer.hpp"
#include "mpm/coupling/field_names.hpp"
#include "mpm_case_builder.hpp"

namespace mpm::coupling {
namespace {

namespace n = names;

CaseDescription floating_block_case() {
  CaseDescription c = testing::empty_case(2, {8, 8, 1}, 0.125);
  c.shape = ShapeKind::gimp;
  c.materials.push_back(testing::elastic(2650.0, 1e6, 0.3));
  BodySpec soil =
      testing::box_body("soil", 0, 2, Vec3d(0.25, 0.25, 0.0), Vec3d(0.75, 0.75, 0.0), 0.125, 2);
  PorousSpec porous;
  porous.porosity = 0.4;
  porous.grain_size = 1e-3;
  porous.permeability_model = PermeabilityModel::constant;
  porous.permeability = 1e-10;
  soil.porous = porous;
  c.bodies.push_back(soil);
  return c;
}

CouplingSpec both_blocks() {
  CouplingSpec spec;
  spec.exchange_grid = ExchangeGridSpec{};
  spec.exchange_grid->writes = {n::solid_fraction, n::solid_velocity, n::solid_bulk_density,
                                n::permeability, n::grain_size};
  spec.exchange_grid->reads = {n::pore_pressure, n::impulse};
  spec.surface = SurfaceSpec{};
  spec.surface->cells = {4};
  spec.surface->writes = {n::bed_elevation};
  spec.surface->reads = {n::bed_traction};
  return spec;
}

struct Rig {
  Solver<2> solver;
  testing::MockChannel* channel;
  MpmCoupling<2> coupling;

  explicit Rig(const CaseDescription& c, const CouplingSpec& spec, double window)
      : solver(c),
        channel(new testing::MockChannel),
        coupling(solver, std::unique_ptr<CouplingChannel>(channel), spec) {
    channel->window = window;
    coupling.declare();
  }
  // The run loop of mpm_coupling.hpp, for one window.
  int run_window(double dt) {
    int steps = 0;
    for (;;) {
      const double step = std::min(dt, coupling.max_time_step());
      const bool last = step >= coupling.max_time_step() - 1e-12;
      solver.step(step);
      coupling.after_step(step);
      channel->advance(step);
      ++steps;
      if (last) return steps;
    }
  }
};

TEST(MpmCoupling, DeclaresTheMeshesAndFieldsAndWritesTheInitialData) {
  Rig rig(floating_block_case(), both_blocks(), 1e-3);
  const auto& ch = *rig.channel;
  ASSERT_EQ(ch.meshes.size(), 2u);
  const auto& grid = std::get<cosim::UniformGrid>(ch.meshes.at(n::exchange_mesh).geometry);
  EXPECT_EQ(grid.dim, 2);
  EXPECT_EQ(grid.cells[0], 8);
  EXPECT_EQ(grid.location, cosim::GridLocation::cell);
  const auto& surface = std::get<cosim::UniformGrid>(ch.meshes.at(n::surface_mesh).geometry);
  EXPECT_EQ(surface.dim, 1);
  EXPECT_EQ(surface.cells[0], 4);
  EXPECT_DOUBLE_EQ(surface.spacing[0], 0.25);
  EXPECT_EQ(ch.write_specs.size(), 6u);
  EXPECT_EQ(ch.write_specs.at(n::solid_velocity).components, 2);
  EXPECT_EQ(ch.write_specs.at(n::solid_fraction).upper_bound, 1.0);
  const auto& impulse = ch.reads.at(n::impulse).spec;
  EXPECT_EQ(impulse.components, 2);
  EXPECT_EQ(impulse.quantity, cosim::Quantity::extensive);
  EXPECT_EQ(impulse.time, cosim::TimeTreatment::integral);
  EXPECT_EQ(ch.reads.at(n::bed_traction).spec.components, 2);
  EXPECT_EQ(ch.reads.at(n::pore_pressure).spec.unit, "Pa");
  for (const auto& [name, spec] : ch.write_specs) EXPECT_EQ(ch.write_count.at(name), 1) << name;
  // The block [0.25, 0.75]^2: total solid volume and a bed at its top over the middle columns.
  double solid_volume = 0.0;
  for (double phi : ch.written.at(n::solid_fraction)) solid_volume += phi * 0.125 * 0.125;
  EXPECT_NEAR(solid_volume, 0.6 * 0.25, 1e-12);
  EXPECT_NEAR(ch.written.at(n::bed_elevation)[1], 0.75, 1e-12);
  EXPECT_NEAR(ch.written.at(n::bed_elevation)[2], 0.75, 1e-12);
  EXPECT_NEAR(ch.written.at(n::bed_elevation)[0], 0.0, 1e-12);  // empty: the grid bottom
  EXPECT_NEAR(ch.written.at(n::bed_elevation)[3], 0.0, 1e-12);
}

TEST(MpmCoupling, WritesOnlyWhenAStepEndsTheWindow) {
  Rig rig(floating_block_case(), both_blocks(), 1e-4);
  const int steps = rig.run_window(0.3e-4);
  EXPECT_EQ(steps, 4);
  EXPECT_EQ(rig.channel->write_count.at(n::solid_fraction), 2);
  EXPECT_EQ(rig.channel->write_count.at(n::bed_elevation), 2);
  rig.run_window(0.3e-4);
  EXPECT_EQ(rig.channel->write_count.at(n::solid_velocity), 3);
  EXPECT_EQ(rig.coupling.diagnostics().writes, 3u);
}

TEST(MpmCoupling, ParticlesGainExactlyTheImpulseReceivedOverAWindow) {
  CouplingSpec spec = both_blocks();
  spec.surface.reset();
  spec.exchange_grid->reads = {n::impulse};
  Rig rig(floating_block_case(), spec, 1e-4);
  std::vector<double> impulse(64 * 2, 0.0);
  for (std::size_t c = 0; c < 64; ++c) {
    impulse[2 * c] = 0.01 * std::sin(static_cast<double>(c));
    impulse[2 * c + 1] = 0.02;
  }
  rig.channel->set(n::impulse, impulse);
  const Vec<2> before = rig.solver.totals().momentum;
  rig.run_window(0.35e-4);
  const Vec<2> gained = rig.solver.totals().momentum - before;
  const auto& d = rig.coupling.diagnostics();
  const Vec<2> applied = d.impulse_total.applied;
  // Empty cells away from the block absorb theirs.
  EXPECT_LT((applied + d.impulse_total.absorbed - d.impulse_total.received).norm(), 1e-14);
  const double error = (gained - applied).norm() / applied.norm();
  std::printf(
      "  momentum gained %.9g, %.9g vs impulse applied %.9g, %.9g: relative error %.2e (tol "
      "1e-12)\n",
      gained[0], gained[1], applied[0], applied[1], error);
  EXPECT_LT(error, 1e-12);
  EXPECT_GT(applied.norm(), 0.5 * 0.02 * 16);  // most of the block's cells
}

TEST(MpmCoupling, HydrostaticPorePressureBuoysTheSolidVolume) {
  CouplingSpec spec = both_blocks();
  spec.surface.reset();
  spec.exchange_grid->reads = {n::pore_pressure};
  Rig rig(floating_block_case(), spec, 1e-4);
  std::vector<double> p(64);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i)
      p[static_cast<std::size_t>(j * 8 + i)] = 1000.0 * 9.81 * (1.0 - (j + 0.5) * 0.125);
  rig.channel->set(n::pore_pressure, p);
  rig.solver.step(1e-5);
  Vec<2> force = Vec<2>::Zero();
  for (const auto& f : rig.solver.particles().external_force) force += f;
  const double buoyancy = 1000.0 * 9.81 * 0.6 * 0.25;
  const double error = std::abs(force[1] - buoyancy) / buoyancy;
  std::printf("  buoyancy %.9g N vs rho_w g (1-n) V = %.9g N: relative error %.2e (tol 1e-12)\n",
              force[1], buoyancy, error);
  EXPECT_LT(error, 1e-12);
  EXPECT_NEAR(rig.solver.particles().pore_pressure[0], 1000.0 * 9.81 * (1.0 - 0.25 - 0.125 / 4),
              1e-9);
}

TEST(MpmCoupling, BedTractionReachesTheSurfaceParticlesInFull) {
  CouplingSpec spec = both_blocks();
  spec.exchange_grid.reset();
  Rig rig(floating_block_case(), spec, 1e-4);
  rig.channel->set(n::bed_traction, {0.0, 0.0, 5.0, -100.0, 7.0, -120.0, 0.0, 0.0});
  rig.solver.step(1e-5);
  Vec<2> force = Vec<2>::Zero();
  for (const auto& f : rig.solver.particles().external_force) force += f;
  const Vec<2> expected = 0.25 * Vec<2>(12.0, -220.0);
  EXPECT_LT((force - expected).norm(), 1e-12 * expected.norm());
}

TEST(MpmCoupling, RigidBodiesAreHeldInTheExchange) {
  CaseDescription c = floating_block_case();
  BodySpec floor =
      testing::box_body("floor", -1, 2, Vec3d(0.0, 0.0, 0.0), Vec3d(1.0, 0.25, 0.0), 0.125, 2);
  floor.rigid = RigidMotion{};
  floor.density_override = 7800.0;
  c.bodies.push_back(floor);
  CouplingSpec spec = both_blocks();
  spec.exchange_grid->hold_at_fixed_faces = false;
  Rig rig(c, spec, 1e-4);
  const auto& rho = rig.channel->written.at(n::solid_bulk_density);
  EXPECT_GT(rho[0], 1e30);         // the floor's cells
  EXPECT_LT(rho[3 * 8 + 3], 1e4);  // the soil's
  // Rows 0-1 under the floor: its particles' domains end at its top face.
  EXPECT_EQ(rig.coupling.diagnostics().held_cells, 16u);
}

TEST(MpmCoupling, UnknownBodyNamesAreInputErrors) {
  CouplingSpec spec = both_blocks();
  spec.exchange_grid->held_bodies = {"sand"};
  Solver<2> solver(floating_block_case());
  EXPECT_THROW(MpmCoupling<2>(solver, std::make_unique<testing::MockChannel>(), spec),
               cosim::InputError);
  spec = both_blocks();
  spec.surface->cells = {4, 4};
  EXPECT_THROW(MpmCoupling<2>(solver, std::make_unique<testing::MockChannel>(), spec),
               cosim::InputError);
}

TEST(MpmCoupling, Works3DOverAWindow) {
  CaseDescription c = testing::empty_case(3, {4, 4, 4}, 0.25);
  c.materials.push_back(testing::elastic(2650.0, 1e6, 0.3));
  c.bodies.push_back(
      testing::box_body("soil", 0, 3, Vec3d(0.25, 0.25, 0.0), Vec3d(0.75, 0.75, 0.5), 0.25, 2));
  CouplingSpec spec = both_blocks();
  spec.surface->cells = {2, 2};
  Solver<3> solver(c);
  auto* channel = new testing::MockChannel;
  channel->window = 1e-4;
  MpmCoupling<3> coupling(solver, std::unique_ptr<CouplingChannel>(channel), spec);
  coupling.declare();
  EXPECT_EQ(std::get<cosim::UniformGrid>(channel->meshes.at(n::surface_mesh).geometry).dim, 2);
  channel->set(n::impulse, std::vector<double>(64 * 3, 1e-3));
  channel->set(n::bed_traction, std::vector<double>(4 * 3, -50.0));
  const Vec<3> before = solver.totals().momentum;
  for (int k = 0; k < 2; ++k) {
    solver.step(0.5e-4);
    coupling.after_step(0.5e-4);
    channel->advance(0.5e-4);
  }
  const auto& d = coupling.diagnostics();
  const Vec<3> gained = solver.totals().momentum - before;
  // Over the window: the applied impulse plus the traction's (4 columns x 0.25 m^2 x -50 Pa x 1e-4
  // s).
  const Vec<3> traction_impulse = Vec<3>::Constant(-50.0 * 0.25 * 4 * 1e-4);
  EXPECT_LT((gained - d.impulse_total.applied - traction_impulse).norm(), 1e-12 * gained.norm());
  EXPECT_EQ(channel->write_count.at(n::bed_elevation), 2);
  // Each column 1/4 covered by the block's top at 0.5 (which has moved by ~1e-8 m).
  for (double b : channel->written.at(n::bed_elevation)) EXPECT_NEAR(b, 0.25 * 0.5, 1e-6);
}

TEST(MpmCoupling, StandaloneObserverRunsTheCaseToItsEndTime) {
  CaseDescription c = floating_block_case();
  c.time.end_time = 2e-4;
  Solver<2> solver(c);
  CouplingObserver<2> observer(cosim::CouplingEndpoint{}, "soil", both_blocks());
  observer.initialize(solver);
  int steps = 0;
  while (observer.is_ongoing() && steps < 1000) {
    const double dt = std::min(solver.stable_time_step(), observer.max_time_step());
    solver.step(dt);
    observer.after_step(solver, dt);
    ++steps;
  }
  observer.finalize();
  EXPECT_NEAR(solver.time(), 2e-4, 1e-12);
  const auto summary = observer.summary(nullptr);
  EXPECT_EQ(summary["participant"], "soil");
  EXPECT_EQ(summary["coupled"], false);
  EXPECT_EQ(summary["writes"], 2);  // the initial data and the one standalone window's end
}

// What a standalone run in windows of 2.5e-4 s leaves: the particles and the
// observer's summary. Driven as run_case drives it: with repeat, every window
// runs twice, the solver going back to the state saved at its start.
struct WindowedRun {
  std::vector<Vec<2>> position, velocity;
  std::vector<Voigt> stress;
  nlohmann::json summary;
  int restores = 0;
};

WindowedRun run_in_windows(bool repeat) {
  CaseDescription c = floating_block_case();
  c.time.end_time = 1e-3;
  c.gravity = Vec3d(0.0, -9.81, 0.0);
  Solver<2> solver(c);
  cosim::CouplingEndpoint endpoint;
  endpoint.repeat_windows = repeat;
  CouplingObserver<2> observer(endpoint, "soil", both_blocks(), 2.5e-4);
  observer.initialize(solver);
  SolverState<2> start;
  WindowedRun run;
  while (observer.is_ongoing()) {
    if (observer.must_save_state()) solver.save(start);
    const double dt = std::min(solver.stable_time_step(), observer.max_time_step());
    solver.step(dt);
    observer.after_step(solver, dt);
    if (observer.must_restore_state()) {
      solver.restore(start);
      ++run.restores;
    }
  }
  observer.finalize();
  run.position = solver.particles().position;
  run.velocity = solver.particles().velocity;
  run.stress = solver.particles().stress;
  run.summary = observer.summary(nullptr);
  return run;
}

TEST(MpmCoupling, RepeatedStandaloneWindowsEndAsAPlainRun) {
  const WindowedRun plain = run_in_windows(false);
  const WindowedRun repeated = run_in_windows(true);
  EXPECT_EQ(plain.restores, 0);
  EXPECT_EQ(repeated.restores, 4);
  EXPECT_EQ(plain.position, repeated.position);
  EXPECT_EQ(plain.velocity, repeated.velocity);
  EXPECT_EQ(plain.stress, repeated.stress);
  EXPECT_EQ(repeated.summary["windows"], 4);
  EXPECT_EQ(repeated.summary["iterations"], 8);
  nlohmann::json attempts = repeated.summary;
  attempts["iterations"] = plain.summary["iterations"];
  EXPECT_EQ(plain.summary, attempts);  // the coupling's record: writes, impulse, traction
  EXPECT_EQ(plain.summary["writes"], 5);
}

}  // namespace
}  // namespace mpm::coupling
