#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "ice/grid/cell_grid.hpp"
#include "ice/grid/grid_fields.hpp"
#include "ice/solver/side_condition.hpp"

namespace ice {

// Viscous stress and heat conduction of one material on the cell grid, as
// explicit face fluxes (Tran et al., MPMICE, eq. 59's Delta(mU)_tau and
// eq. 60's div q with q = k grad T), so the sums over the cells change only
// through the sides. Per unit volume over dt:
//
//   momentum_i += dt div(phi tau)_i,  tau = mu (grad U + grad U^T) - (2/3) mu (div U) I,
//   energy     += dt div(phi k grad T).
//
// Face coefficients are the harmonic means of the cells' phi mu (phi k):
// the flux through a face between a material-filled and a nearly empty cell
// is set by the nearly empty one, as for conductances in series. On the
// face normal to d, dU_i/dx_d is the two-cell difference and the
// derivatives along the face the mean of the two cells' central
// differences (one-sided at the sides).
//
// Sides: every side type of the ICE solver carries no viscous flux (wall is
// a symmetry plane, the open types are zero-gradient), so momentum is
// conserved exactly; for heat a side with a temperature conducts through
// half a cell to it, the others are insulated.
template <int Dim>
class Diffusion {
 public:
  using Velocity = std::array<CellField, static_cast<std::size_t>(Dim)>;

  Diffusion(const CellGrid<Dim>& grid, const std::array<SideCondition, 2 * Dim>& sides);

  // `viscosity` mu per cell [Pa s] (molecular plus turbulent),
  // `volume_fraction` phi per cell. Throws std::invalid_argument for wrong
  // sizes or a negative viscosity.
  void add_viscous_momentum(std::span<const double> viscosity,
                            std::span<const double> volume_fraction, const Velocity& velocity,
                            double dt, Velocity& momentum) const;

  // `conductivity` k per cell [W/(m K)]. Throws as above.
  void add_heat_conduction(std::span<const double> conductivity,
                           std::span<const double> volume_fraction,
                           std::span<const double> temperature, double dt,
                           std::span<double> energy) const;

 private:
  // dU_j/dx_j in `cell` by central differences (one-sided at the sides).
  double central_difference(const CellField& u, int cell, int direction) const;

  CellGrid<Dim> grid_;
  std::array<SideCondition, 2 * Dim> sides_;
};

// Smagorinsky's eddy viscosity (Tran et al., MPMICE, eqs. 17-19) per cell,
// mu_t = rho (C_s Delta)^2 |S|, |S| = sqrt(2 S:S), Delta = V^(1/Dim), from
// the velocity's central differences; `density` is the material's intrinsic
// density [kg/m3].
template <int Dim>
void smagorinsky_viscosity(const CellGrid<Dim>& grid,
                           const std::array<CellField, static_cast<std::size_t>(Dim)>& velocity,
                           std::span<const double> density, double constant,
                           std::span<double> viscosity);

// The explicit diffusion limit: dt <= 1 / (2 D sum_d 1/dx_d^2) with D the
// largest diffusivity (mu / rho or k / (rho c_v)) [s]; +infinity for D = 0.
template <int Dim>
double diffusion_time_step(const CellGrid<Dim>& grid, double largest_diffusivity);

}  // namespace ice
