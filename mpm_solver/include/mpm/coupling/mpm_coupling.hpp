#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "mpm/coupling/body_roles.hpp"
#include "mpm/coupling/coupling_channel.hpp"
#include "mpm/coupling/coupling_spec.hpp"
#include "mpm/coupling/exchange_grid.hpp"
#include "mpm/coupling/heat_exchange_increment.hpp"
#include "mpm/coupling/momentum_exchange_increment.hpp"
#include "mpm/coupling/surface_grid.hpp"
#include "mpm/coupling/surface_traction.hpp"
#include "mpm/solver/solver.hpp"

namespace cosim {
class Participant;
}

// The MPM side of the coupling (architecture.md §3-4): what the solver writes to
// and reads from the coupler, and how what it reads acts on the particles.
//
// Call order in the run loop (CouplingObserver runs exactly this inside
// mpm::run_case):
//
//   auto coupling = mpm::coupling::attach_coupling(solver, participant, spec);
//   coupling->declare();                      // meshes, fields, initial data (before initialize)
//   participant.initialize(start, end);
//   while (participant.is_coupling_ongoing()) {
//     const double dt = std::min(solver.stable_time_step(), coupling->max_time_step());
//     solver.step(dt);                        // the coupling's force source reads the pore
//                                             // pressure, the step's impulse share and the bed
//                                             // traction, and applies them; its heat source
//                                             // the step's share of the exchanged heat
//     coupling->after_step(dt);               // writes, when this step ends the window
//     participant.advance(dt);                // exchanges, when the window is complete
//     if (participant.must_restore_state()) coupling->restore_state();
//     if (participant.is_window_complete()) coupling->log_held_warnings();
//     if (participant.must_save_state()) coupling->save_state();
//   }
//
// (the solver's own state is saved and restored alongside, by run_case).
//
// Exchange grid (mesh "mpm_grid", cell-centred, Dim-D): writes solid_fraction,
// solid_velocity, solid_bulk_density, permeability, grain_size (see
// porous_fields_writer.hpp); reads pore_pressure (applied as -phi_s grad p,
// pore_pressure_force.hpp) and momentum_exchange_impulse (split over the
// particles, momentum_exchange_increment.hpp). When the case conducts heat
// it also writes solid_temperature and solid_heat_capacity
// (thermal_fields_writer.hpp) and reads heat_exchange_energy (shared over
// the particles by heat capacity, heat_exchange_increment.hpp, as a heat
// rate E_p / dt over the step). Surface (mesh "mpm_surface",
// cell-centred, (Dim-1)-D): writes bed_elevation (bed_elevation.hpp), reads
// bed_traction (surface_traction.hpp).
//
// Everything read acts through one particle force source registered on the
// solver, which runs at the start of each solver step (before the participant
// advances): for a step of dt the force on particle p is
//   -(1 - n_p) V_p grad p  +  J_p / dt  +  (bed traction share),
// so the momentum it adds over the step is exactly the impulse share J_p
// (less what fixed grid faces and local damping remove).
namespace mpm::coupling {

template <int Dim>
struct CouplingDiagnostics {
  std::size_t capped_solid_fraction_cells = 0;  // summed over all writes
  std::size_t overfilled_cells = 0;             // summed over all writes (spread_overfilled_cells)
  std::size_t held_cells = 0;                   // at the last write
  std::size_t writes = 0;                       // times the fields were written
  Vec<Dim> pore_pressure_force = Vec<Dim>::Zero();  // last step [N]
  ImpulseSplit<Dim> impulse_step;                   // last step [kg m/s]
  ImpulseSplit<Dim> impulse_total;                  // whole run
  TractionTotals<Dim> traction_step;                // last step [N]
  HeatSplit heat_step;                              // last step [J]
  HeatSplit heat_total;                             // whole run
};

template <int Dim>
class MpmCoupling {
 public:
  // Registers the particle force source (and, when it reads heat, the heat
  // source) on the solver. The coupling state they use is shared with the
  // solver, so the solver may outlive this object. Thermal fields on a
  // solver that does not conduct heat are an InputError.
  MpmCoupling(Solver<Dim>& solver, std::unique_ptr<CouplingChannel> channel, CouplingSpec spec);
  ~MpmCoupling();
  MpmCoupling(const MpmCoupling&) = delete;
  MpmCoupling& operator=(const MpmCoupling&) = delete;

  // Declares the meshes and fields, then writes the initial fields (sent by
  // initialize() as the initial data).
  void declare();
  double max_time_step() const;
  // After solver.step(dt), before participant.advance(dt): writes the
  // fields when this step ends the window.
  void after_step(double dt);
  // Writes every declared field from the current particles.
  void write_fields();

  // What the coupling carries from step to step (its diagnostics; the
  // particles are the solver's to save): kept at a window's start, put
  // back when the window runs again, which also drops the warnings held.
  void save_state();
  void restore_state();
  // The warnings of write_fields() wait for the window to be complete.
  void log_held_warnings();

  const ExchangeGrid<Dim>* exchange_grid() const;
  const SurfaceGrid<Dim>* surface() const;
  const std::vector<BodyRole>& roles() const;
  const CouplingDiagnostics<Dim>& diagnostics() const;

 private:
  struct State;
  std::shared_ptr<State> state_;
};

// The production glue: a coupling over a cosim::Participant (coupled or
// standalone). The participant must outlive the coupling.
template <int Dim>
std::unique_ptr<MpmCoupling<Dim>> attach_coupling(Solver<Dim>& solver,
                                                  cosim::Participant& participant,
                                                  const CouplingSpec& spec);

extern template class MpmCoupling<2>;
extern template class MpmCoupling<3>;

}  // namespace mpm::coupling
