#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "cosim/participant.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {

// The ICE side of the porous soil <-> fluid pairing (DESIGN.md §4, Tran et
// al., MPMICE's mixture theory), on the mesh `ice_cells`:
//   reads   solid_fraction [1] and solid_velocity [m/s] (state, from the
//           soil): the porosity n = 1 - phi_s the fluids fill (eqs. 42-43)
//           and the solid velocity of eq. 75's divergence constraint;
//           momentum_exchange_impulse [kg m/s] (extensive window integral):
//           the momentum the coupler's implicit drag exchange gives the
//           fluid, added step by step in proportion to dt;
//   writes  pore_pressure [Pa], fluid_velocity [m/s] (the fluids' mass-
//           weighted velocity) and fluid_bulk_density [kg/m3] (their summed
//           bulk density), for the soil and the exchange.
// The porosity is floored at minimum_porosity so a cell packed with soil
// keeps some pore volume.
template <int Dim>
class PorousCoupling {
 public:
  static constexpr const char* mesh_name = "ice_cells";

  explicit PorousCoupling(double minimum_porosity = 0.05) : minimum_porosity_(minimum_porosity) {}

  // Declares the mesh and fields, then writes the initial fields.
  void declare(cosim::Participant& participant, const IceSolver<Dim>& solver);
  // At a window start: the received porosity and solid velocity. On the
  // first window the fluids are laid into the pores (bulk densities scaled
  // by n, pressures kept), later ones compress or expand them.
  void read_medium(const cosim::Participant& participant, IceSolver<Dim>& solver,
                   bool first_window);
  // Each step: the step's share of the window's exchange impulse.
  void add_impulse(cosim::Participant& participant, double dt, IceSolver<Dim>& solver);
  void write_fields(cosim::Participant& participant, const IceSolver<Dim>& solver);

 private:
  double minimum_porosity_;
  std::vector<double> buffer_;
  std::vector<double> porosity_;
  std::array<std::vector<double>, static_cast<std::size_t>(Dim)> solid_velocity_;
  std::vector<double> pressure_, velocity_, density_;
};

}  // namespace ice
