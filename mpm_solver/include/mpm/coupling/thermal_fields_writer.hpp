#pragma once

#include <vector>

#include "mpm/coupling/exchange_grid.hpp"
#include "mpm/coupling/over_ranks.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::coupling {

// The solid's thermal state per exchange cell, as the coupler's implicit
// energy exchange reads it (Tran et al., MPMICE, eqs. 66 and 70). With
// C_p = m_p c_p, w_pc the conservative weights of ExchangeGrid and V_c the
// cell volume:
//   T_s       = sum_p w_pc C_p T_p / sum_p w_pc C_p   [K]
//   (rho c)_s = sum_p w_pc C_p / V_c                  [J/(m^3 K)]
// so sum_c (rho c)_s V_c T_s = sum_p C_p T_p exactly. A cell without thermal
// solid has (rho c)_s = 0 and takes no part in the exchange; its T_s is the
// heat-capacity-weighted mean of the cells around it (3^Dim block), or of
// the whole solid when they have none either, never a made-up 0 K that a
// consistent map near the solid's edge would blend in.
struct ThermalFields {
  std::vector<double> solid_temperature;
  std::vector<double> solid_heat_capacity;
};

template <int Dim>
// On a rank of a decomposed MPM the sums are every rank's (`sum_over_ranks`).
ThermalFields thermal_fields(const ExchangeGrid<Dim>& grid, const Particles<Dim>& particles,
                             const SumOverRanks& sum_over_ranks = {});

}  // namespace mpm::coupling
