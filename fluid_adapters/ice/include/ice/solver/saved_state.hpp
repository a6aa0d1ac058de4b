#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "ice/grid/grid_fields.hpp"
#include "ice/solver/fluid_state.hpp"

namespace ice {

// Everything an IceSolver carries from one step to the next, as
// IceSolver::save_state copies it out and restore_state copies it back: a
// coupling window that must run again (implicit coupling) starts from it
// and repeats the first attempt bit for bit. Kept from window to window, so
// that each save reuses the buffers of the last.
template <int Dim>
struct SavedIceState {
  FluidState<Dim> fluid;
  double time = 0.0;
  long steps = 0;
  // What the last pressure equilibration left for the next step: each
  // material's adiabatic compressibility and the mixture's.
  std::vector<CellField> kappa;
  CellField mixture_kappa;
  // The pressure solve's warm start: the last step's increment.
  CellField pressure_increment;
  // The last step's face rate sum_d |U_FC,d| / dx_d, which limits the next
  // stable_time_step.
  double last_face_rate = 0.0;
  // The last step's face velocities and pressures (face_velocity(),
  // face_pressure(), solid_pressure_force()).
  std::vector<FaceField<Dim>> face_velocity;
  FaceField<Dim> face_pressure;
  // The porous solid's drag (set_solid_drag) and what it carries from step
  // to step: the solid's exchange velocity, the impulse it has received and
  // the face velocities the next step's drag starts from.
  bool solid_drag_on = false;
  CellField solid_drag;
  CellField solid_bulk_density;
  std::array<CellField, static_cast<std::size_t>(Dim)> solid_exchange_velocity;
  std::vector<double> solid_impulse;
  std::vector<FaceField<Dim>> previous_face_velocity;
  // The received porosity the next step must still displace (empty: none).
  CellField porosity_to_displace;
};

}  // namespace ice
