#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpm/coupling/body_roles.hpp"
#include "mpm/coupling/exchange_grid.hpp"
#include "mpm/coupling/over_ranks.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::coupling {

// The solid phase per exchange cell, as the coupler's implicit momentum
// exchange reads it (Tran et al., MPMICE, eqs. 7 and 131; architecture.md §4).
// With w_pc the conservative weights of ExchangeGrid and V_c the cell volume:
//   phi_s       = sum_p (1 - n_p) V_p w_pc / V_c      (capped at 1)
//   rho_bar_s   = sum_p m_p w_pc / V_c                 (m_p is the solid mass)
//   u_s         = sum_p m_p v_p w_pc / sum_p m_p w_pc
//   kappa, D50  = mass-weighted means over the porous particles (each
//                 particle's permeability follows its porosity, Pan et al.
//                 2021, eq. 76); 0 where no porous particle reaches the cell,
// with the sums of the points that are not held taken after the cells their
// domains overfill have handed their excess to neighbours with room
// (spread_overfilled_cells: the sums are moved, not changed).
// A cell is held when more than half of its solid mass (of its volume, for
// massless rigid bodies) belongs to held particles and the solid not held
// fills at most 10 % of it; its rho_bar_s is written as held_density_factor x
// max(rho_bar_s, 1 kg/m^3), which makes the exchange's solid velocity
// increment dt K / rho_bar_s vanish, and its u_s is the held particles'
// mass-weighted velocity alone (the tips of a deformable body's domains do
// not move the held solid). A cell shared by held solid and more deformable
// solid than that (sand sliding over a cut cell of a rigid bed) is not held
// and takes the deformable solid's velocity: its fluid moves with the sand,
// the bed only takes pore space. On a rank of a decomposed MPM the sums are
// every rank's (`sum_over_ranks`), so each rank gets the whole fields.
struct PorousFields {
  std::vector<double> solid_fraction;
  std::vector<double> solid_velocity;     // Dim per cell, cell-major
  std::vector<double> solid_volume_flux;  // sum_i phi_i U_i [m/s], Dim per cell
  std::vector<double> solid_bulk_density;
  std::vector<double> permeability;
  std::vector<double> grain_size;
  std::vector<std::uint8_t> held;
  std::size_t capped_cells = 0;      // cells where phi_s exceeded 1 + 1e-3 after the spreading
  std::size_t overfilled_cells = 0;  // cells whose points' domains covered more than the cell
};

template <int Dim>
PorousFields porous_fields(const ExchangeGrid<Dim>& grid, const Particles<Dim>& particles,
                           const std::vector<BodyRole>& roles,
                           const std::vector<std::uint8_t>& held, double held_density_factor,
                           const SumOverRanks& sum_over_ranks = {});

}  // namespace mpm::coupling
