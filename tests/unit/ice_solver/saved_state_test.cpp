// IceSolver::save_state and restore_state, which implicit coupling uses to
// run a window again: steps taken after a restore repeat those taken after
// the save bit for bit (state, face values, pressure warm start, step-size
// limit, the solid's impulse), as often as the window is repeated, and a
// solver that saved and restored steps on exactly as one that never did.
// Also prints what a save and a restore cost against a step.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ice/case/load_case.hpp"
#include "ice/case/make_solver.hpp"
#include "ice/eos/linear_water.hpp"
#include "ice/solver/ice_solver.hpp"
#include "same_bits.hpp"

namespace ice {
namespace {

using cosim::testing::same_bits;

// A water column collapsing in air under a fixed-pressure top: the two-fluid
// face exchange, viscosity, conduction, heat exchange and the multigrid
// pressure solve all take part.
const char* const dam_break = R"(kind: ice_case
name: dam_break
dimension: 2
grid: {origin: [0.0, 0.0], upper: [0.2, 0.1], cells: [40, 20]}
gravity: [0.0, -9.81]
end_time: 1.0
materials:
  water:
    eos: {type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8}
    viscosity: 1.0e-3
    thermal_conductivity: 0.6
  air:
    eos: {type: ideal_gas, gas_constant: 287.0, heat_capacity_ratio: 1.4}
    viscosity: 1.8e-5
    thermal_conductivity: 0.026
exchange:
  - {materials: [water, air], momentum: 1.0e15, heat: 1.0e5}
initial:
  fill: air
  temperature: 293.15
  regions:
    - {box: {lower: [0.0, 0.0], upper: [0.05, 0.08]}, fill: water, temperature: 283.15}
boundaries:
  y_max: {type: fixed_pressure, pressure: 101325}
)";

// The fields of two saved states that differ in any bit, by name.
template <int Dim>
std::vector<std::string> differences(const SavedIceState<Dim>& a, const SavedIceState<Dim>& b) {
  std::vector<std::string> names;
  const auto field = [&](const std::string& name, const std::vector<double>& x,
                         const std::vector<double>& y) {
    if (!same_bits(x, y)) names.push_back(name);
  };
  const auto faces = [&](const std::string& name, const FaceField<Dim>& x,
                         const FaceField<Dim>& y) {
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
      field(fmt::format("{}[{}]", name, d), x[d], y[d]);
  };
  field("pressure", a.fluid.pressure, b.fluid.pressure);
  field("porosity", a.fluid.porosity, b.fluid.porosity);
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    field(fmt::format("solid_velocity[{}]", d), a.fluid.solid_velocity[d],
          b.fluid.solid_velocity[d]);
    field(fmt::format("solid_exchange_velocity[{}]", d), a.solid_exchange_velocity[d],
          b.solid_exchange_velocity[d]);
  }
  if (a.fluid.materials.size() != b.fluid.materials.size()) names.push_back("materials");
  for (std::size_t m = 0; m < std::min(a.fluid.materials.size(), b.fluid.materials.size()); ++m) {
    const MaterialState<Dim>& x = a.fluid.materials[m];
    const MaterialState<Dim>& y = b.fluid.materials[m];
    field(fmt::format("bulk_density {}", m), x.bulk_density, y.bulk_density);
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
      field(fmt::format("velocity[{}] {}", d, m), x.velocity[d], y.velocity[d]);
    field(fmt::format("temperature {}", m), x.temperature, y.temperature);
    field(fmt::format("density {}", m), x.density, y.density);
    field(fmt::format("volume_fraction {}", m), x.volume_fraction, y.volume_fraction);
    field(fmt::format("specific_volume {}", m), x.specific_volume, y.specific_volume);
    field(fmt::format("kappa {}", m), a.kappa[m], b.kappa[m]);
    faces(fmt::format("face_velocity {}", m), a.face_velocity[m], b.face_velocity[m]);
    faces(fmt::format("previous_face_velocity {}", m), a.previous_face_velocity[m],
          b.previous_face_velocity[m]);
  }
  field("mixture_kappa", a.mixture_kappa, b.mixture_kappa);
  field("pressure_increment", a.pressure_increment, b.pressure_increment);
  faces("face_pressure", a.face_pressure, b.face_pressure);
  field("solid_drag", a.solid_drag, b.solid_drag);
  field("solid_bulk_density", a.solid_bulk_density, b.solid_bulk_density);
  field("solid_impulse", a.solid_impulse, b.solid_impulse);
  if (std::memcmp(&a.time, &b.time, sizeof(double)) != 0) names.push_back("time");
  if (a.steps != b.steps) names.push_back("steps");
  if (std::memcmp(&a.last_face_rate, &b.last_face_rate, sizeof(double)) != 0)
    names.push_back("last_face_rate");
  if (a.solid_drag_on != b.solid_drag_on) names.push_back("solid_drag_on");
  return names;
}

// What a run of steps gives besides the state: every step's length and
// report, and the impulse the solid took.
struct StepRecord {
  std::vector<double> values;
  bool operator==(const StepRecord& other) const { return same_bits(values, other.values); }
};

// How a window is stepped: what is read at its start (as a coupled run
// reads the porous medium) and whether the solid's impulse is taken after
// each step (a coupled run with the drag) or left to add up.
template <int Dim>
struct Window {
  std::function<void(IceSolver<Dim>&)> read = [](IceSolver<Dim>&) {};
  bool take_impulse = true;
};

// `steps` steps at the CFL limit.
template <int Dim>
StepRecord run_window(IceSolver<Dim>& solver, int steps, const Window<Dim>& window) {
  StepRecord record;
  window.read(solver);
  std::vector<double> impulse(static_cast<std::size_t>(solver.grid().cell_count() * Dim));
  for (int s = 0; s < steps; ++s) {
    const double dt = std::min(solver.stable_time_step(0.4, false), 1e-3);
    const StepReport report = solver.advance(dt);
    EXPECT_TRUE(report.accepted);
    record.values.insert(
        record.values.end(),
        {dt, report.courant, static_cast<double>(report.pressure_iterations),
         report.pressure_residual, static_cast<double>(report.equilibration_iterations),
         report.volume_closure});
    if (solver.has_solid_drag() && window.take_impulse) {
      solver.take_solid_impulse(impulse);
      record.values.insert(record.values.end(), impulse.begin(), impulse.end());
    }
  }
  return record;
}

// What the solver shows between steps: the steps the CFL rule allows, the
// face velocities and pressures, the pressure's force on a solid, the totals.
template <int Dim>
std::vector<double> observed(const IceSolver<Dim>& solver) {
  std::vector<double> values{solver.stable_time_step(0.4, false),
                             solver.stable_time_step(0.4, true), solver.time()};
  const auto append = [&](const std::vector<double>& v) {
    values.insert(values.end(), v.begin(), v.end());
  };
  for (std::size_t m = 0; m < solver.materials().size(); ++m)
    for (const std::vector<double>& faces : solver.face_velocity(m)) append(faces);
  for (const std::vector<double>& faces : solver.face_pressure()) append(faces);
  std::vector<double> force(static_cast<std::size_t>(solver.grid().cell_count() * Dim));
  solver.solid_pressure_force(force);
  append(force);
  for (const MaterialTotals& t : solver.totals()) {
    values.insert(values.end(), {t.mass, t.internal_energy, t.kinetic_energy});
    values.insert(values.end(), t.momentum.begin(), t.momentum.end());
  }
  return values;
}

void expect_no_differences(const std::vector<std::string>& names, const std::string& when) {
  for (const std::string& name : names) ADD_FAILURE() << when << ": " << name << " differs";
}

// A solver and its twin, built alike and stepped alike for a few steps; then
// the first is saved and runs the window (first the `stray` one, which reads
// other values, as an implicit coupling's first iterates do) four times,
// restored before each attempt but the first, while the twin runs `window`
// once. After each attempt of `window` the first holds what the twin does
// (state, step records), right after each restore it shows what it showed
// when saved, and in the end both step on alike.
template <int Dim, class Make>
void expect_repeated_windows_reproduce(Make make, const Window<Dim>& window,
                                       const Window<Dim>& stray) {
  const std::unique_ptr<IceSolver<Dim>> solver = make();
  const std::unique_ptr<IceSolver<Dim>> twin = make();
  const int lead_in = 5, window_steps = 8, after = 6;
  const Window<Dim> lead{.take_impulse = window.take_impulse};
  run_window(*solver, lead_in, lead);
  run_window(*twin, lead_in, lead);

  SavedIceState<Dim> saved, twin_end, attempt_end;
  solver->save_state(saved);
  const std::vector<double> at_save = observed(*solver);
  const StepRecord expected = run_window(*twin, window_steps, window);
  twin->save_state(twin_end);
  run_window(*solver, window_steps, stray);
  for (int attempt = 1; attempt <= 3; ++attempt) {
    solver->restore_state(saved);
    EXPECT_TRUE(same_bits(observed(*solver), at_save)) << "restored for attempt " << attempt;
    const StepRecord record = run_window(*solver, window_steps, window);
    solver->save_state(attempt_end);
    EXPECT_TRUE(record == expected) << "attempt " << attempt << ": the steps differ";
    expect_no_differences(differences(twin_end, attempt_end), fmt::format("attempt {}", attempt));
  }
  EXPECT_TRUE(run_window(*solver, after, lead) == run_window(*twin, after, lead));
  solver->save_state(attempt_end);
  twin->save_state(twin_end);
  expect_no_differences(differences(twin_end, attempt_end), "after the window");
}

// The stray attempt gets heat and momentum, as from the coupler's exchanges.
TEST(IceSavedState, RepeatedWindowsOfADamBreakAreBitwiseAlike) {
  const CaseDescription c = load_case_text(dam_break, "dam_break.yaml");
  const Window<2> exchanged{.read = [](IceSolver<2>& solver) {
    const auto cells = static_cast<std::size_t>(solver.grid().cell_count());
    solver.add_heat(std::vector<double>(cells, 1e-3));
    solver.add_momentum(std::vector<double>(2 * cells, 1e-7));
  }};
  expect_repeated_windows_reproduce<2>([&] { return make_solver<2>(c); }, Window<2>{}, exchanged);
}

// Water flowing through a porous solid that moves and drags on it (the
// coupled run's `drag: ice`): the solid's exchange velocity, its impulse and
// the face velocities the drag remembers are carried from step to step.
// As in a coupled run the window starts by reading the medium, after the
// save, and reads it again when repeated; the stray attempt reads another
// medium. Then windows without reads, after a stray attempt that read
// another medium (the impulse left to add up) or switched the drag off.
TEST(IceSavedState, RepeatedWindowsThroughAMovingPorousSolidAreBitwiseAlike) {
  const CellGrid<2> grid(CellGrid<2>::Point::Zero(), CellGrid<2>::Point(0.1, 0.1), {12, 6});
  const auto cells = static_cast<std::size_t>(grid.cell_count());
  std::vector<double> porosity(cells), drag(cells), solid_density(cells);
  std::array<CellField, 2> solid_velocity{CellField(cells), CellField(cells, 0.0)};
  for (std::size_t c = 0; c < cells; ++c) {
    const double x = grid.cell_centre(static_cast<int>(c))[0];
    const bool soil = x > 0.4 && x < 0.9;
    porosity[c] = soil ? 0.4 + 0.01 * static_cast<double>(c % 5) : 1.0;
    drag[c] = soil ? 2.0e5 : 0.0;
    solid_density[c] = soil ? 1590.0 : 0.0;
    solid_velocity[0][c] = soil ? 1e-3 : 0.0;
  }
  std::array<SideCondition, 4> sides{};
  sides[0].type = sides[1].type = SideType::fixed_pressure;
  sides[0].pressure = 101325.0 + 2.0e4;
  sides[1].pressure = 101325.0;
  const auto make = [&] {
    FluidState<2> state;
    state.materials.resize(1);
    MaterialState<2>& water = state.materials[0];
    water.bulk_density.assign(cells, 999.8);
    water.temperature.assign(cells, 283.15);
    for (auto& u : water.velocity) u.assign(cells, 0.0);
    state.pressure.assign(cells, 101325.0);
    auto solver = std::make_unique<IceSolver<2>>(
        grid,
        std::vector<FluidMaterial>{
            {"water", std::make_shared<LinearWater>(LinearWaterParameters{}), 1e-3, 0.0}},
        ExchangeCoefficients::none(1), sides, Eigen::Vector2d(0.0, -9.81), state);
    solver->set_porous_medium(porosity, solid_velocity, PorosityChange::fill_pores);
    solver->set_solid_drag(drag, solid_density);
    return solver;
  };
  const auto read_medium = [&](double change) {
    return [&, change](IceSolver<2>& solver) {
      std::vector<double> moved = solver.state().porosity;
      std::array<CellField, 2> velocity = solid_velocity;
      std::vector<double> k = drag, density = solid_density;
      for (std::size_t c = 0; c < cells; ++c) {
        if (moved[c] < 1.0) moved[c] *= 1.0 - change;
        velocity[1][c] += change;
        k[c] *= 1.0 + change;
        density[c] *= 1.0 + change;
      }
      solver.set_porous_medium(moved, velocity);
      solver.set_solid_drag(k, density);
    };
  };
  expect_repeated_windows_reproduce<2>(make, Window<2>{.read = read_medium(0.0)},
                                       Window<2>{.read = read_medium(0.01)});
  expect_repeated_windows_reproduce<2>(make, Window<2>{.take_impulse = false},
                                       Window<2>{.read = read_medium(0.01), .take_impulse = false});
  const auto no_drag = [](IceSolver<2>& solver) { solver.set_solid_drag({}, {}); };
  expect_repeated_windows_reproduce<2>(make, Window<2>{}, Window<2>{.read = no_drag});
}

}  // namespace
}  // namespace ice
