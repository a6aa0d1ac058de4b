#pragma once

#include <vector>

#include "cosim/participant.hpp"
#include "mpm/depth_averaged/cell_deposit.hpp"
#include "mpm/depth_averaged/depth_averaged_solver.hpp"

namespace mpm {

// The depth-averaged mass as a participant of a coupled job with the
// two-phase shallow water (swe_fluid, `two_phase` with coupling.reads:
// [solid_layer]), on the mesh "ground": the solver's grid as cell-centred
// cells in plan view (the terrain must not be inclined: the water's grid is
// horizontal).
//
//   writes  column_volume, column_mass, column_momentum, structured_mass
//           (the points' sums per cell, CellDeposit: conserved exactly),
//           released_fluid_volume (integral: the fluid of eq. 27), and
//           bed_elevation (the terrain at the cells' centres);
//   reads   momentum_exchange_impulse (integral: the water's drag on the
//           columns, distributed to the points by mass, conserved exactly)
//           and free_surface_elevation (the water's surface, for buoyancy
//           and the base's relief, eqs. 39 and 54); both optional.
//
// The window's order: start_window() applies what the water sent at the
// last window's end; the solver steps, after_step() writing the released
// fluid's rate; at the window's last step, after_step() writes the columns
// as they stand, which the water lays under itself for the next window.
class DepthAveragedCoupling {
 public:
  DepthAveragedCoupling(cosim::Participant& participant, const DepthAveragedSolver& solver,
                        double fluid_density);

  // Declares the mesh and fields and writes their first values (before
  // Participant::initialize).
  void declare(const DepthAveragedSolver& solver);
  void start_window(DepthAveragedSolver& solver);
  void after_step(DepthAveragedSolver& solver, double dt, bool window_ends);

  // Totals since the start: the impulse received [kg m/s] and the fluid
  // released [m^3]; the impulse no point could take (none left) [kg m/s].
  Vec<2> impulse_received() const { return impulse_received_; }
  double fluid_released() const { return fluid_released_; }
  // What the last window released, which the water takes in the next (none
  // after the job's last window).
  double fluid_released_last_window() const { return released_last_window_; }
  Vec<2> impulse_unplaced() const { return impulse_unplaced_; }

 private:
  void write_columns(const DepthAveragedSolver& solver);

  cosim::Participant& participant_;
  CellDeposit deposit_;
  double fluid_density_;
  bool reads_impulse_ = false, reads_surface_ = false;
  Vec<2> impulse_received_ = Vec<2>::Zero(), impulse_unplaced_ = Vec<2>::Zero();
  double fluid_released_ = 0.0;
  double released_this_window_ = 0.0, released_last_window_ = 0.0;
};

}  // namespace mpm
