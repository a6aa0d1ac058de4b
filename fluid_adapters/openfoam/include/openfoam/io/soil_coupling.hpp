#pragma once

#include <cmath>
#include <vector>

#include "cosim/participant.hpp"
#include "openfoam/case/case_description.hpp"
#include "openfoam/cloud/soil_cloud.hpp"
#include "openfoam/io/case_mesh.hpp"
#include "openfoam/io/cell_neighbours.hpp"
#include "openfoam/io/foam_fields.hpp"

namespace openfoam {

// What the adapter exchanges with the MPM soil through the coupler, on the
// case's cells (architecture.md §4, the job's `momentum_exchange` with
// `solved_by: fluid`):
//   reads   solid_fraction, solid_velocity, solid_bulk_density, drag_coefficient K
//           (the job's law);
//   writes  pore_pressure p, fluid_velocity (interstitial U),
//           fluid_bulk_density alphac rho, water_fraction alphac alpha.water,
//           momentum_exchange_impulse (what the soil receives in the window).
// MPPICInterFoam applies the drag to the water itself, through the parcels;
// their diameter is chosen per cell so that the cloud's Ergun-Wen-Yu
// coefficient in water is K / n at the relative speed of the previous
// window's end (ergun_wen_yu.hpp: the cloud's water takes the whole pressure
// gradient); in air OpenFOAM's drag follows the air's viscosity and density.
// The soil receives n times the reaction of that drag, as the cloud gave it
// to the water (its UTrans, the mean over the window's steps, x steps:
// window_step_means.hpp; the law on the window's end fields where OpenFOAM
// wrote none): with the MPM's own -phi_s grad p the mixture's
// momentum is that of Tran et al., MPMICE, eqs. 7-8 (at steady state the
// soil takes the whole seepage force grad p).
//
// The water the soil displaces: the solver sees the soil's volume fraction
// only between windows (cell mode), so inside a window its continuity is
// div(n u) = 0 where the mixture's is div(n u_f + phi_s U_s) = 0. The
// solver's u is then the physical u_f + phi_s U_s / n exactly, and with the
// parcels moving at U_s / n its drag sees the physical U_s - u_f; the fields
// read back are shifted to the physical u_f. Where a held body (a rigid
// bed) shares a cell with a moving one, phi_s U_s overstates the solids'
// volume flux (phi_s counts the bed, U_s is the moving body's): the job then
// sends mpm_solver's `solid_volume_flux` F = sum phi_i U_i (an optional read),
// the solver's u is u_f + F / n and the parcels move at U_s + F / n. This is what carries the pore
// pressure of a compacting skeleton (Terzaghi) through stock MPPICInterFoam.
class SoilCoupling {
 public:
  SoilCoupling(const CaseDescription& description, const CaseMesh& mesh,
               const CaseProperties& properties, CellNeighbours neighbours);

  void declare(cosim::Participant& participant) const;

  // The window's parcels from the soil's fields received at its start and
  // the fluid's at its start.
  const SoilParcels& parcels(const cosim::Participant& participant, const FoamFields& start);

  // 1 - phi_s per cell (phi_s capped at max_solid_fraction) from the soil's
  // fields received last: the fluid fraction MPPICInterFoam will see.
  std::vector<double> fluid_fraction(const cosim::Participant& participant);

  // porosity_zones: each cell's Darcy coefficient d = K / (n^2 mu_water) [1/m^2]
  // (0 without soil) from the soil's fields received at the window's start:
  // interFoam's water takes the whole pressure gradient and its U is the
  // superficial velocity, so at steady state grad p = -mu d U gives the
  // Darcy flux of the job's law (n grad p = -K u_f, U = n u_f).
  const std::vector<double>& darcy_coefficients(const cosim::Participant& participant);

  // The fields sent at the window's end (`end`'s velocity shifted to the
  // physical u_f), and the momentum check of the window of `steps` OpenFOAM
  // steps.
  struct MomentumCheck {
    double cloud_on_fluid = 0.0;  // |sum| of OpenFOAM's UTrans x steps [kg m/s]
    double law_on_fluid = 0.0;    // |sum| of the law's -f V T
    double to_soil = 0.0;         // |sum| of what the soil receives
    double mismatch = 0.0;        // |cloud - law| / sum |law| over the cells
    // Cells whose drag was limited to beta T = 1 (the window longer than the
    // soil's relaxation time 1 / beta, beta = n K_cloud / rho_bar_s), and
    // the shortest relaxation time among them [s].
    std::size_t limited_cells = 0;
    double shortest_relaxation = INFINITY;
  };
  MomentumCheck write(cosim::Participant& participant, FoamFields& end, double window, long steps);

  // What the coupling carries from one window to the next (the water's
  // velocity at the last window's end, which sizes the parcels): saved at a
  // window's start, put back when the window must run again.
  std::vector<double> carried_state() const { return fluid_velocity_; }
  void restore(std::vector<double> carried) { fluid_velocity_ = std::move(carried); }

  static constexpr const char* mesh_name = "openfoam_cells";

 private:
  double plane_volume(std::size_t c) const;
  void read_soil(const cosim::Participant& participant);
  void extend_pressure_into_impermeable_cells(std::vector<double>& p) const;
  bool porosity_zones() const { return c_.soil.model == SoilModel::porosity_zones; }
  double pore_fraction(std::size_t c) const;
  MomentumCheck write_porosity_zones(cosim::Participant& participant, FoamFields& end,
                                     double window);
  void write_fields(cosim::Participant& participant, const FoamFields& end,
                    const std::vector<double>& fluid_fraction,
                    const std::vector<double>& impulse_rate) const;

  const CaseDescription& c_;
  const CaseMesh& mesh_;
  CaseProperties properties_;
  CellNeighbours neighbours_;
  FluidProperties water_;
  FluidProperties air_;
  int dim_;
  std::vector<double> solid_fraction_;
  std::vector<double> solid_velocity_;  // dim per cell
  std::vector<double> volume_flux_;     // the solids' sum phi_i U_i [m/s], dim per cell
  std::vector<double> drag_;
  std::vector<double> solid_density_;   // rho_bar_s; above 1e20: a held (rigid) solid
  std::vector<double> diameter_;        // per cell; 0 where no parcel
  std::vector<double> darcy_;           // porosity_zones: per cell d [1/m^2]; 0 where no soil
  std::vector<double> fluid_velocity_;  // physical u_f at the last window's end, dim per cell
  SoilParcels parcels_;
};

}  // namespace openfoam
