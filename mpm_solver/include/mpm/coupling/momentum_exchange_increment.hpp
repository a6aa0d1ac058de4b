#pragma once

#include <span>
#include <vector>

#include "mpm/coupling/body_roles.hpp"
#include "mpm/coupling/exchange_grid.hpp"
#include "mpm/coupling/share_over_particles.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::coupling {

// Totals of one split [kg m/s] (per unit depth in 2D); absorbed: by cells
// with only rigid solid, or empty with no solid around.
template <int Dim>
using ImpulseSplit = ShareTotals<Dim>;

// The momentum the implicit exchange gives the solid in a step (the step's
// share of the window's impulse, architecture.md §4), cell by cell, split over the
// deformable particles by their mass weight in the cell (share_over_particles):
//   J_p = sum_c J_c m_p w_pc / sum_q m_q w_qc
// with the conservative weights w_pc of the fields written, so
// sum_p J_p = sum_c J_c to round-off over the cells that hold deformable
// solid. A cell without any solid (the coupler's mappings smear the impulse
// a little past the solid's edge) passes its impulse to its neighbours
// (3^Dim block) by their deformable mass. Rigid bodies take no coupling
// force: a cell holding only rigid solid, or an empty cell with no
// deformable neighbour, absorbs its impulse (reported in `absorbed`).
//
// SplitWeight::solid_volume shares a cell's value by the particles' solid
// volume (1 - n_p) V_p w_pc instead, rigid particles included, whose shares
// are absorbed: the fluid solver's pressure force per cell,
// -phi_s grad P V_c with phi_s counting every solid in the cell, then gives
// each deformable particle its own -(1 - n_p) V_p grad P (Tran et al.,
// MPMICE, eq. 7), also where it shares the cell with a rigid bed (by mass the
// deformable particles would take the bed's share too).
enum class SplitWeight { deformable_mass, solid_volume };

template <int Dim>
ImpulseSplit<Dim> split_impulse(const ExchangeGrid<Dim>& grid, std::span<const double> cell_impulse,
                                const Particles<Dim>& particles, const std::vector<BodyRole>& roles,
                                std::vector<Vec<Dim>>& particle_impulse,
                                SplitWeight weighting = SplitWeight::deformable_mass,
                                const SumOverRanks& sum_over_ranks = {});

}  // namespace mpm::coupling
