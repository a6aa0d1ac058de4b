#pragma once

#include <span>
#include <vector>

#include "mpm/coupling/exchange_grid.hpp"
#include "mpm/coupling/over_ranks.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::coupling {

// Totals of one split [J] (per unit depth in 2D).
struct HeatSplit {
  double received = 0.0;  // sum over the cells
  double applied = 0.0;   // sum over the particles
  double absorbed = 0.0;  // cells with no thermal solid in or around them
};

// The heat the implicit energy exchange gives the solid in a step (the
// step's share of the window's heat_exchange_energy), cell by cell, split
// over the thermal particles by their heat capacity weight in the cell
// (share_over_particles):
//   E_p = sum_c E_c C_p w_pc / sum_q C_q w_qc,   C_p = m_p c_p,
// so sum_p E_p = sum_c E_c to round-off and the exchange's heat lands on
// the particles in proportion to their share of the cell's solid heat
// capacity, which it was computed from. Rigid thermal bodies take their
// share: their temperature is a state like any other. A cell without
// thermal solid passes its heat to the neighbouring cells (3^Dim block)
// by their heat capacity, or absorbs it when none has any.
template <int Dim>
HeatSplit split_heat(const ExchangeGrid<Dim>& grid, std::span<const double> cell_heat,
                     const Particles<Dim>& particles, std::vector<double>& particle_heat,
                     const SumOverRanks& sum_over_ranks = {});

}  // namespace mpm::coupling
