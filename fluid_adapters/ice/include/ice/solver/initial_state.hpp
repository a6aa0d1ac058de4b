#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "ice/grid/cell_grid.hpp"
#include "ice/grid/grid_fields.hpp"
#include "ice/solver/fluid_material.hpp"
#include "ice/solver/fluid_state.hpp"

namespace ice {

// What each cell starts as: the material that fills it (index into the
// materials), its pressure, temperature and velocity.
template <int Dim>
struct CellFill {
  std::vector<int> material;
  CellField pressure;                                             // [Pa]
  CellField temperature;                                          // [K]
  std::array<CellField, static_cast<std::size_t>(Dim)> velocity;  // [m/s]
};

// The state of a filled grid: in each cell the filling material takes the
// volume fraction 1 - (N - 1) f_min and every other material f_min (ICE
// needs every material in every cell), each at the cell's pressure and
// temperature, so rhobar_f = phi_f rho_f(P, T). Throws std::invalid_argument
// for sizes that do not fit, a material index out of range or f_min outside
// [0, 1 / N), and cosim::NumericalError for a pressure at or below a
// material's minimum pressure.
template <int Dim>
FluidState<Dim> make_initial_state(const CellGrid<Dim>& grid,
                                   const std::vector<FluidMaterial>& materials,
                                   const CellFill<Dim>& fill, double minimum_volume_fraction);

// The discrete hydrostatic pressure of a filled grid, the rest state of the
// ICE step: gravity must lie along one grid direction; along it each column
// of cells is integrated from `top_pressure` on the side gravity points away
// from, P_top = P_ref + rho_top g dx / 2 and P_next = P_prev + g dx (rho_prev
// + rho_next) / 2 with the mixture densities rho = sum_f rhobar_f at the
// cells' own pressures (a few fixed-point sweeps). With K -> inf between
// the materials this is the pressure at which the face velocities of
// eqs. 44-48 vanish and the cell momentum of eq. 59 with the face pressure
// of eq. 54 balances each cell's weight. Zero gravity gives top_pressure
// everywhere. Throws std::invalid_argument for gravity along two directions.
template <int Dim>
CellField hydrostatic_pressure(const CellGrid<Dim>& grid,
                               const std::vector<FluidMaterial>& materials,
                               const std::vector<int>& fill_material, const CellField& temperature,
                               const Eigen::Matrix<double, Dim, 1>& gravity, double top_pressure,
                               double minimum_volume_fraction);

}  // namespace ice
