#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "cosim/participant.hpp"
#include "ice/case/case_description.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {

// The ICE side of the porous soil <-> fluid pairing (architecture.md §4, Tran et
// al., MPMICE's mixture theory), on the mesh `ice_cells`:
//   reads   solid_fraction [1] and solid_velocity [m/s] (state, from the
//           soil): the porosity n = 1 - phi_s the fluids fill (eqs. 42-43)
//           and the solid velocity of eq. 75's divergence constraint;
//           drag: coupler  momentum_exchange_impulse [kg m/s] (extensive
//                          window integral): the momentum the coupler's
//                          implicit drag exchange gives the fluid, added
//                          step by step in proportion to dt;
//           drag: ice      drag_coefficient [kg/(m3 s)] and
//                          solid_bulk_density [kg/m3] (state): the drag is
//                          solved in every step with the solid as an
//                          exchange material (IceSolver::set_solid_drag);
//   writes  pore_pressure [Pa]; pore_pressure_force [N] (extensive), the
//           pressure's force on the solid per cell as the fluids feel it
//           (IceSolver::solid_pressure_force); fluid_velocity [m/s] (the fluids' mass-
//           weighted velocity) and fluid_bulk_density [kg/m3] (their summed
//           bulk density), for the soil and the exchange; with drag: ice
//           also momentum_exchange_impulse, the momentum the solid received
//           from the drag over the window (the coupler hands it to the solid).
// With heat_exchange it also writes fluid_temperature [K] and
// fluid_heat_capacity [J/(m3 K)] and reads heat_exchange_energy [J]
// (extensive window integral), added step by step (IceSolver::add_heat).
// The porosity is floored at the configured minimum so a cell packed with
// soil keeps some pore volume.
template <int Dim>
class PorousCoupling {
 public:
  static constexpr const char* mesh_name = "ice_cells";

  explicit PorousCoupling(CouplingDescription description = {}) : description_(description) {}

  // Declares the mesh and fields, then writes the initial fields. On
  // several ranks: the whole grid, and `part` the cells the solver holds.
  void declare(cosim::Participant& participant, IceSolver<Dim>& solver,
               std::optional<std::pair<cosim::Mesh, cosim::MeshPart>> decomposed = std::nullopt);
  // At a window start (and, when the fields vary within the window, at each
  // step's middle, relative_time after now): the received porosity and solid
  // velocity (and with drag: ice the drag coefficient and solid bulk
  // density). On the first window the fluids are laid into the pores (bulk
  // densities scaled by n, pressures kept), later ones compress or expand
  // them.
  void read_medium(const cosim::Participant& participant, IceSolver<Dim>& solver, bool first_window,
                   double relative_time = 0.0);
  // After each accepted step: with drag: coupler the step's share of the
  // window's exchange impulse is added to the fluids; with drag: ice the
  // momentum the solid received in the step is written (as the rate of the
  // window integral momentum_exchange_impulse).
  void exchange_step(cosim::Participant& participant, double dt, IceSolver<Dim>& solver);
  void write_fields(cosim::Participant& participant, IceSolver<Dim>& solver);

 private:
  // The longest window an explicit exchange of porosity and pore pressure
  // stands: the time the pore water's pressure wave takes across an
  // exchange cell holding solid (architecture.md §3); +infinity without solid.
  double explicit_window_limit(const IceSolver<Dim>& solver) const;

  CouplingDescription description_;
  std::vector<double> buffer_;
  std::vector<double> porosity_;
  std::array<std::vector<double>, static_cast<std::size_t>(Dim)> solid_velocity_;
  std::vector<double> drag_, solid_density_;
  std::vector<double> pressure_, velocity_, density_, force_, capacity_, temperature_, modulus_;
  bool warned_ = false;
};

}  // namespace ice
