// The solid side of the fluid-solid energy exchange: the thermal fields
// written per exchange cell, the exchanged heat shared over the particles
// by heat capacity, and what reaches the particles over whole windows.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cosim/config/document.hpp"
#include "mock_channel.hpp"
#include "mpm/coupling/coupling_spec.hpp"
#include "mpm/coupling/field_names.hpp"
#include "mpm/coupling/heat_exchange_increment.hpp"
#include "mpm/coupling/mpm_coupling.hpp"
#include "mpm/coupling/thermal_fields_writer.hpp"
#include "mpm_case_builder.hpp"
#include "particle_fixtures.hpp"

namespace mpm::coupling {
namespace {

namespace n = names;

ExchangeGrid<2> grid_4x4() {
  const Grid<2> g = make_grid<2>(Vec<2>::Zero(), Vec<2>::Constant(0.25), {4, 4}, ShapeKind::linear);
  return ExchangeGrid<2>::covering(g, 1);
}

// One particle at `x` with heat capacity C [J/K] and temperature T.
void add_point(Particles<2>& particles, const Vec<2>& x, double C, double T) {
  const std::size_t p = particles.size();
  particles.resize(p + 1);
  particles.position[p] = x;
  particles.volume[p] = particles.initial_volume[p] = 1e-3;
  particles.mass[p] = 1.0;
  particles.heat_capacity[p] = C;
  particles.temperature[p] = T;
}

TEST(MpmCouplingHeat, ThermalFieldsOnAKnownLayout) {
  const auto grid = grid_4x4();
  Particles<2> particles;
  // Two points at the centre of cell (1, 1), one at the centre of (3, 0),
  // and one of a body that is not thermal (no heat capacity) in (0, 3).
  add_point(particles, grid.centre({1, 1}), 1000.0, 300.0);
  add_point(particles, grid.centre({1, 1}), 3000.0, 400.0);
  add_point(particles, grid.centre({3, 0}), 500.0, 250.0);
  add_point(particles, grid.centre({0, 3}), 0.0, 1000.0);
  const ThermalFields f = thermal_fields(grid, particles);
  const double V = 0.25 * 0.25;
  EXPECT_DOUBLE_EQ(f.solid_temperature[grid.flat({1, 1})],
                   (1000.0 * 300.0 + 3000.0 * 400.0) / 4000.0);
  EXPECT_DOUBLE_EQ(f.solid_heat_capacity[grid.flat({1, 1})], 4000.0 / V);
  EXPECT_DOUBLE_EQ(f.solid_temperature[grid.flat({3, 0})], 250.0);
  EXPECT_DOUBLE_EQ(f.solid_heat_capacity[grid.flat({3, 0})], 500.0 / V);
  // Cells without thermal solid: no heat capacity; the temperature of the
  // solid around them, else of the whole solid.
  EXPECT_EQ(f.solid_heat_capacity[grid.flat({0, 3})], 0.0);
  EXPECT_EQ(f.solid_heat_capacity[grid.flat({2, 2})], 0.0);
  EXPECT_DOUBLE_EQ(f.solid_temperature[grid.flat({0, 2})], 375.0);  // beside (1, 1)
  EXPECT_DOUBLE_EQ(f.solid_temperature[grid.flat({2, 1})],
                   (4000.0 * 375.0 + 500.0 * 250.0) / 4500.0);
  EXPECT_DOUBLE_EQ(f.solid_temperature[grid.flat({3, 3})],
                   (4000.0 * 375.0 + 500.0 * 250.0) / 4500.0);
  EXPECT_DOUBLE_EQ(f.solid_temperature[grid.flat({0, 3})],
                   1625000.0 / 4500.0);  // its point is not thermal
}

TEST(MpmCouplingHeat, ThermalFieldsKeepTheSolidsHeatContent) {
  const auto grid = grid_4x4();
  auto particles = testing::random_particles<2>(500, Vec<2>::Zero(), Vec<2>::Ones(), 17);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double content = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    particles.heat_capacity[p] = 800.0 * particles.mass[p];
    particles.temperature[p] = 280.0 + 40.0 * u(rng);
    content += particles.heat_capacity[p] * particles.temperature[p];
  }
  const ThermalFields f = thermal_fields(grid, particles);
  double cells = 0.0;
  for (std::size_t c = 0; c < grid.size(); ++c)
    cells += f.solid_heat_capacity[c] * grid.cell_volume() * f.solid_temperature[c];
  const double error = std::abs(cells - content) / content;
  std::printf("  sum_c (rho c)_s V T_s vs sum_p m c T: relative error %.2e (tolerance 1e-13)\n",
              error);
  EXPECT_LT(error, 1e-13);
}

TEST(MpmCouplingHeat, SharedByHeatCapacityConservingEachCellsHeat) {
  const auto grid = grid_4x4();
  Particles<2> particles;
  // Cell (1, 1): heat capacities 1000 and 3000 J/K; cell (3, 3) is empty
  // beside nothing thermal but (2, 2), which holds 2000 J/K.
  add_point(particles, grid.centre({1, 1}), 1000.0, 300.0);
  add_point(particles, grid.centre({1, 1}), 3000.0, 300.0);
  add_point(particles, grid.centre({2, 2}), 2000.0, 300.0);
  add_point(particles, grid.centre({0, 3}), 0.0, 300.0);  // not thermal
  std::vector<double> heat(grid.size(), 0.0);
  heat[grid.flat({1, 1})] = 40.0;
  heat[grid.flat({3, 3})] = 6.0;   // no solid: passed on to (2, 2)
  heat[grid.flat({0, 3})] = -5.0;  // only the non-thermal point, and (1, 2) holds nothing: absorbed
  std::vector<double> particle_heat;
  const HeatSplit split = split_heat(grid, heat, particles, particle_heat);
  EXPECT_DOUBLE_EQ(particle_heat[0], 10.0);
  EXPECT_DOUBLE_EQ(particle_heat[1], 30.0);
  EXPECT_DOUBLE_EQ(particle_heat[2], 6.0);
  EXPECT_EQ(particle_heat[3], 0.0);
  EXPECT_DOUBLE_EQ(split.received, 41.0);
  EXPECT_DOUBLE_EQ(split.applied, 46.0);
  EXPECT_DOUBLE_EQ(split.absorbed, -5.0);

  // Random points and heat: what the particles get is what the cells hold.
  auto random = testing::random_particles<2>(2000, Vec<2>::Zero(), Vec<2>::Ones(), 5);
  for (std::size_t p = 0; p < random.size(); ++p) random.heat_capacity[p] = 700.0 * random.mass[p];
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double& e : heat) e = 100.0 * u(rng);
  const HeatSplit all = split_heat(grid, heat, random, particle_heat);
  double sum = 0.0;
  for (double e : particle_heat) sum += e;
  const double error = std::abs(sum - all.received) / std::abs(all.received);
  std::printf("  heat over 2000 particles vs the cells': relative error %.2e (tolerance 1e-12)\n",
              error);
  EXPECT_LT(error, 1e-12);
  EXPECT_EQ(all.absorbed, 0.0);
}

// A thermal porous block in an insulated box, read heat over windows.
CaseDescription thermal_block_case() {
  CaseDescription c = testing::empty_case(2, {8, 8, 1}, 0.125);
  c.materials.push_back(testing::material_from_yaml(
      "type: linear_elastic\ndensity: 2650\nyoungs_modulus: 1.0e6\npoisson_ratio: 0.3\n"
      "specific_heat: 835\nthermal_conductivity: 0.4\n"));
  BodySpec soil =
      testing::box_body("soil", 0, 2, Vec3d(0.25, 0.25, 0.0), Vec3d(0.75, 0.75, 0.0), 0.125, 2);
  soil.porous = PorousSpec{.porosity = 0.4, .grain_size = 1e-3};
  soil.initial_temperature = 300.0;
  c.bodies.push_back(soil);
  c.thermal.enabled = true;
  return c;
}

CouplingSpec thermal_exchange() {
  CouplingSpec spec;
  spec.exchange_grid = ExchangeGridSpec{};
  spec.exchange_grid->writes = {n::solid_fraction, n::solid_temperature, n::solid_heat_capacity};
  spec.exchange_grid->reads = {n::heat};
  return spec;
}

TEST(MpmCouplingHeat, DeclaresTheThermalFields) {
  Solver<2> solver(thermal_block_case());
  auto* channel = new testing::MockChannel;
  MpmCoupling<2> coupling(solver, std::unique_ptr<CouplingChannel>(channel), thermal_exchange());
  coupling.declare();
  const auto& T = channel->write_specs.at(n::solid_temperature);
  EXPECT_EQ(T.unit, "K");
  EXPECT_EQ(T.components, 1);
  EXPECT_EQ(T.quantity, cosim::Quantity::intensive);
  EXPECT_EQ(T.time, cosim::TimeTreatment::state);
  EXPECT_EQ(channel->write_specs.at(n::solid_heat_capacity).unit, "J/(m^3 K)");
  const auto& heat = channel->reads.at(n::heat).spec;
  EXPECT_EQ(heat.unit, "J");
  EXPECT_EQ(heat.components, 1);
  EXPECT_EQ(heat.quantity, cosim::Quantity::extensive);
  EXPECT_EQ(heat.time, cosim::TimeTreatment::integral);
  // The block [0.25, 0.75]^2 at 300 K: its heat capacity rho_s (1 - n) c per
  // unit volume over the cells it covers, and 300 K everywhere.
  double capacity = 0.0;
  for (double rc : channel->written.at(n::solid_heat_capacity)) capacity += rc * 0.125 * 0.125;
  EXPECT_NEAR(capacity, 2650.0 * 0.6 * 835.0 * 0.25, 1e-9 * capacity);
  for (double T_s : channel->written.at(n::solid_temperature)) EXPECT_NEAR(T_s, 300.0, 1e-10);
}

TEST(MpmCouplingHeat, ParticlesGainExactlyTheHeatReceivedOverWindows) {
  Solver<2> solver(thermal_block_case());
  auto* channel = new testing::MockChannel;
  channel->window = 1e-4;
  MpmCoupling<2> coupling(solver, std::unique_ptr<CouplingChannel>(channel), thermal_exchange());
  coupling.declare();
  std::vector<double> heat(64, 0.0);
  // Heat on the cells that hold solid (the particles' domains fill exactly
  // the block's cells; an empty cell with no solid beside it would absorb).
  const auto& capacity = channel->written.at(n::solid_heat_capacity);
  for (std::size_t c = 0; c < 64; ++c)
    heat[c] = capacity[c] > 0.0 ? 50.0 + 30.0 * std::sin(static_cast<double>(c)) : 0.0;
  channel->set(n::heat, heat);
  const double before = solver.totals().thermal_energy;
  int steps = 0;
  for (int window = 0; window < 2; ++window) {
    for (;;) {
      const double step = std::min(0.35e-4, coupling.max_time_step());
      const bool last = step >= coupling.max_time_step() - 1e-12;
      solver.step(step);
      coupling.after_step(step);
      channel->advance(step);
      ++steps;
      if (last) break;
    }
  }
  const auto& d = coupling.diagnostics();
  double window_heat = 0.0;
  for (double e : heat) window_heat += e;
  const double gained = solver.totals().thermal_energy - before;
  const double read_error =
      std::abs(d.heat_total.received - 2.0 * window_heat) / (2.0 * window_heat);
  const double balance =
      std::abs(d.heat_total.applied + d.heat_total.absorbed - d.heat_total.received);
  // The gain is the difference of two sums of m c T ~ 1e8 J/m: round-off is
  // measured against the thermal energy itself.
  const double error = std::abs(gained - d.heat_total.applied) / before;
  std::printf(
      "  %d steps over 2 windows: heat read %.12g J/m (2 windows x %.12g), applied %.12g, absorbed "
      "%.3g; "
      "thermal energy gained %.12g J/m: error %.2e of the thermal energy %.3g J/m (tolerance "
      "1e-14), "
      "%.2e of the heat\n",
      steps, d.heat_total.received, window_heat, d.heat_total.applied, d.heat_total.absorbed,
      gained, error, before, std::abs(gained - d.heat_total.applied) / d.heat_total.applied);
  EXPECT_EQ(steps, 6);
  EXPECT_LT(read_error, 1e-13);
  EXPECT_LT(balance, 1e-12 * window_heat);
  EXPECT_LT(error, 1e-14);
  EXPECT_NEAR(solver.totals().external_heat, d.heat_total.applied, 1e-12 * d.heat_total.applied);
  EXPECT_EQ(d.heat_total.absorbed, 0.0);
  EXPECT_EQ(channel->write_count.at(n::solid_temperature), 3);  // initial data and two window ends
}

TEST(MpmCouplingHeat, ThermalFieldsNeedACaseThatConductsHeat) {
  CaseDescription c = thermal_block_case();
  c.thermal.enabled = false;
  Solver<2> solver(c);
  try {
    MpmCoupling<2>(solver, std::make_unique<testing::MockChannel>(), thermal_exchange());
    ADD_FAILURE() << "no InputError";
  } catch (const cosim::InputError& e) {
    std::printf("  InputError: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("coupling.exchange_grid.writes"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("solid_temperature"), std::string::npos);
  }
}

CouplingSpec read(const std::string& yaml, bool heat_conduction) {
  const auto doc = cosim::config::Document::load_string(yaml, "case.yaml");
  return read_coupling(doc.root()["coupling"], 2, heat_conduction);
}

TEST(MpmCouplingHeat, ThermalFieldsJoinTheDefaultsOnlyWhenTheCaseConductsHeat) {
  const CouplingSpec plain = read("coupling:\n  exchange_grid: {}\n", false);
  EXPECT_EQ(plain.exchange_grid->writes.size(), 5u);
  EXPECT_EQ(plain.exchange_grid->reads.size(), 2u);
  EXPECT_FALSE(plain.exchange_grid->reads_field(n::heat));
  const CouplingSpec thermal = read("coupling:\n  exchange_grid: {}\n", true);
  EXPECT_EQ(thermal.exchange_grid->writes.size(), 7u);
  EXPECT_TRUE(thermal.exchange_grid->writes_field(n::solid_temperature));
  EXPECT_TRUE(thermal.exchange_grid->writes_field(n::solid_heat_capacity));
  EXPECT_TRUE(thermal.exchange_grid->reads_field(n::heat));
  EXPECT_TRUE(thermal.exchange_grid->reads_field(n::impulse));
  // Listed explicitly, the lists are the user's.
  const CouplingSpec listed = read("coupling:\n  exchange_grid: {reads: [pore_pressure]}\n", true);
  EXPECT_FALSE(listed.exchange_grid->reads_field(n::heat));
  try {
    read(
        "coupling:\n  exchange_grid:\n    reads: [pore_pressure,\n            "
        "heat_exchange_energy]\n",
        false);
    ADD_FAILURE() << "no InputError";
  } catch (const cosim::InputError& e) {
    std::printf("  InputError: %s\n", e.what());
    EXPECT_EQ(e.where().line, 4);
    EXPECT_NE(std::string(e.what()).find("coupling.exchange_grid.reads"), std::string::npos);
  }
}

}  // namespace
}  // namespace mpm::coupling
