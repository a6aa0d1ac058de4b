// Solver::save and Solver::restore: the steps after a restore repeat the
// steps after the save bit for bit, with every kind of state a step carries
// (Mohr-Coulomb softening and cohesion degradation, a free rigid body in
// frictional contact, heat conduction to a fixed-temperature face, a ramped
// load, the accumulated energy), on one thread and on two.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "mpm/case/load_case.hpp"
#include "mpm/solver/solver.hpp"
#include "replaced_text.hpp"
#include "same_bits.hpp"
#include "scratch_directory.hpp"

namespace mpm {
namespace {

using cosim::testing::replaced;
using cosim::testing::same_bits;

// A cohesive sand column that collapses under its weight and a ramped
// pressure, a boulder (free rigid body) falling on it, a fixed floor, and
// the column cooled through the x_min face.
const char* const collapsing_column = R"(kind: mpm_case
dimension: 2
grid: {origin: [0, 0], upper: [1, 0.5], cells: [40, 20]}
time: {end_time: 1, safety_factor: 0.4}
gravity: [0, -9.81]
materials:
  sand:
    type: mohr_coulomb
    density: 2000
    youngs_modulus: 2.0e6
    poisson_ratio: 0.3
    friction_angle: 35
    residual_friction_angle: 25
    softening_rate: 10
    dilatancy: rowe
    cohesion: 500
    tensile_strength: 200
    cohesion_degradation: {critical_volumetric_strain: 0.005}
    specific_heat: 800
    thermal_conductivity: 50
bodies:
  - name: column
    material: sand
    geometry: {box: {min: [0, 0.1], max: [0.3, 0.4]}}
    temperature: 350
  - name: floor
    rigid: {motion: fixed}
    density: 2000
    geometry: {box: {min: [0, 0], max: [1, 0.1]}}
  - name: boulder
    rigid: {motion: free}
    density: 3000
    geometry: {box: {min: [0.1, 0.425], max: [0.2, 0.475]}}
contact: {enabled: true, friction: 0.3}
boundaries: {x_min: slip, x_max: slip, y_min: fixed, y_max: free}
thermal: {x_min: {type: fixed_temperature, temperature: 300}}
loads:
  - {name: push, body: column, region: {min: [0, 0.38], max: [0.1, 0.4]}, pressure: 2000,
     ramp_time: 0.01}
threads: 1
)";

// Every particle array, the grid of the last step and the totals.
template <int Dim>
void expect_same_bits(const Solver<Dim>& a, const Solver<Dim>& b) {
  const Particles<Dim>& p = a.particles();
  const Particles<Dim>& q = b.particles();
#define EXPECT_SAME(array) EXPECT_TRUE(same_bits(p.array, q.array)) << #array
  EXPECT_SAME(position);
  EXPECT_SAME(velocity);
  EXPECT_SAME(deformation_gradient);
  EXPECT_SAME(half_length);
  EXPECT_SAME(mass);
  EXPECT_SAME(initial_volume);
  EXPECT_SAME(volume);
  EXPECT_SAME(stress);
  EXPECT_SAME(plastic_strain);
  EXPECT_SAME(damage);
  EXPECT_SAME(internal);
  EXPECT_SAME(porosity);
  EXPECT_SAME(initial_porosity);
  EXPECT_SAME(permeability);
  EXPECT_SAME(grain_size);
  EXPECT_SAME(pore_pressure);
  EXPECT_SAME(temperature);
  EXPECT_SAME(temperature_gradient);
  EXPECT_SAME(heat_capacity);
  EXPECT_SAME(external_force);
  EXPECT_SAME(external_heat);
  EXPECT_SAME(body);
#undef EXPECT_SAME
  EXPECT_TRUE(same_bits(a.grid().mass, b.grid().mass));
  EXPECT_TRUE(same_bits(a.grid().velocity, b.grid().velocity));
  EXPECT_TRUE(same_bits(a.grid().temperature, b.grid().temperature));
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.step_count(), b.step_count());
  const Totals<Dim> s = a.totals();
  const Totals<Dim> t = b.totals();
  for (const auto& [name, x, y] :
       {std::tuple{"kinetic_energy", s.kinetic_energy, t.kinetic_energy},
        std::tuple{"contact_dissipation", s.contact_dissipation, t.contact_dissipation},
        std::tuple{"boundary_dissipation", s.boundary_dissipation, t.boundary_dissipation},
        std::tuple{"external_work", s.external_work, t.external_work},
        std::tuple{"internal_work", s.internal_work, t.internal_work},
        std::tuple{"plastic_dissipation", s.plastic_dissipation, t.plastic_dissipation},
        std::tuple{"thermal_energy", s.thermal_energy, t.thermal_energy},
        std::tuple{"heat_through_faces", s.heat_through_faces, t.heat_through_faces}})
    EXPECT_EQ(std::memcmp(&x, &y, sizeof(double)), 0) << name;
}

template <int Dim>
void run_steps(Solver<Dim>& solver, int steps) {
  for (int k = 0; k < steps; ++k) solver.step(solver.stable_time_step());
}

double largest(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end());
}

// Runs `warm_up` steps, saves, runs a window of `window` steps, restores and
// runs it again: the solver ends where an identical solver that never went
// back ends, bit for bit.
void expect_restored_window_repeats(const std::string& text, int warm_up, int window) {
  const cosim::testing::ScratchDirectory dir;
  const CaseDescription description = load_case_text(text, dir / "case.yaml");
  Solver<2> repeated(description);
  Solver<2> plain(description);
  run_steps(repeated, warm_up);
  run_steps(plain, warm_up);

  SolverState<2> start;
  repeated.save(start);
  const double plastic_strain_at_start = largest(repeated.particles().plastic_strain);
  run_steps(repeated, window);
  // The window changed what the restore must undo.
  EXPECT_GT(largest(repeated.particles().plastic_strain), plastic_strain_at_start);
  EXPECT_GT(largest(repeated.particles().damage), 0.0);
  EXPECT_GT(repeated.totals().contact_dissipation, 0.0);
  repeated.restore(start);
  EXPECT_EQ(repeated.step_count(), static_cast<std::size_t>(warm_up));
  run_steps(repeated, window);
  run_steps(plain, window);
  expect_same_bits(repeated, plain);

  // The same buffers again, for the next window.
  repeated.save(start);
  run_steps(repeated, window);
  repeated.restore(start);
  run_steps(repeated, window);
  run_steps(plain, window);
  expect_same_bits(repeated, plain);
}

// The same case on a grid four times finer, the floor three cells thick:
// 11 648 particles (9216 of sand), enough for the parallel loops.
std::string finer(const std::string& text) {
  return replaced(replaced(text, "cells: [40, 20]", "cells: [160, 80]"),
                  "min: [0, 0], max: [1, 0.1]", "min: [0, 0.08125], max: [1, 0.1]");
}

TEST(MpmSolverState, RestoredWindowRepeatsBitForBit) {
  expect_restored_window_repeats(collapsing_column, 150, 40);
}

TEST(MpmSolverState, RestoredWindowRepeatsBitForBitOnTwoThreads) {
  expect_restored_window_repeats(replaced(finer(collapsing_column), "threads: 1", "threads: 2"),
                                 100, 20);
}

TEST(MpmSolverState, RestoringAStateNeverSavedIsAnInternalError) {
  const cosim::testing::ScratchDirectory dir;
  Solver<2> solver(load_case_text(collapsing_column, dir / "case.yaml"));
  const SolverState<2> never_saved;
  EXPECT_FALSE(never_saved.is_saved());
  try {
    solver.restore(never_saved);
    FAIL() << "restored a state never saved";
  } catch (const cosim::Error& e) {
    EXPECT_EQ(e.code(), cosim::ExitCode::internal_error);
  }
}

}  // namespace
}  // namespace mpm
