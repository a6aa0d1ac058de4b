#pragma once

#include <initializer_list>
#include <span>
#include <vector>

#include "ice/advection/limiter.hpp"
#include "ice/grid/cell_grid.hpp"
#include "ice/grid/grid_fields.hpp"

namespace ice {

// Conservative advection of cell-centred densities by face velocities, the
// step of Tran et al., MPMICE, eqs. 77-80 written per unit volume:
//
//   q_c^{n+1} V = q_c^L V - dt sum_faces q_face U_face A_face,
//
// for q = rhobar (mass), rhobar u (momentum), rhobar c_v T (energy) and
// rhobar v (specific volume), all with the same face velocities U_FC.
//
// Scheme: unsplit donor-cell flux form, one flux per face, subtracted from
// one cell and added to the other, so the total sum_c q_c V changes only by
// round-off. q_face is the upwind (donor) cell's limited linear profile taken
// at the centroid of the slab that leaves through the face in dt,
//
//   q_face = q_D +- (1 - |U| dt / dx_d) dq_D / 2,
//
// with dq_D the donor's limited difference along the face normal (see
// Limiter), + on the donor's upper face. This is van Leer's (1977) second
// order upwind scheme for linear advection, applied direction by direction;
// Uintah's ICE evaluates its limited gradient at the same outflux-slab
// centroid ("compatible fluxes for van Leer advection", VanderHeyden and
// Kashiwa 1998), where it also limits the specific values q / rhobar; here
// each density is limited on its own.
//
// Properties: a uniform q under a discretely divergence-free U_FC stays
// uniform (its differences vanish, so q_face = q on every face); in 1D the
// limited schemes are TVD for |U| dt/dx <= 1; in Dim dimensions they create
// no new extrema under a uniform velocity when sum_d |U_d| dt/dx_d <= 1/2,
// and first_order none up to 1.
//
// Domain boundary: faces on the boundary carry the given velocity (0 at a
// wall, so no flux). Where it is not zero the face value is the boundary
// cell's own value (a zero-gradient ghost): outflow takes the boundary cell's
// value, inflow brings in that same value. The boundary cells' differences
// normal to the boundary are zero, so the scheme is first order there.
template <int Dim>
class Advector {
 public:
  Advector(const CellGrid<Dim>& grid, Limiter limiter);

  const CellGrid<Dim>& grid() const { return grid_; }
  Limiter limiter() const { return limiter_; }

  // Advances every field of `fields` (densities per unit volume, one value
  // per cell) in place over dt with the face velocities U_FC. Throws
  // std::invalid_argument for fields or face velocities of the wrong size or
  // a negative or non-finite dt, and cosim::NumericalError for a face whose
  // |U| dt / dx exceeds 1 or is not finite. Allocates nothing.
  void advance(const FaceField<Dim>& face_velocity, double dt,
               std::span<const std::span<double>> fields);
  void advance(const FaceField<Dim>& face_velocity, double dt,
               std::initializer_list<std::span<double>> fields) {
    advance(face_velocity, dt, std::span<const std::span<double>>(fields.begin(), fields.size()));
  }
  // In a porous medium (porosity n per cell, 0 < n <= 1): each density is
  // reconstructed per unit of pore space, q / n, and a face carries the
  // donor's profile in the donor's pores, q_face = n_D (q / n)_face. Across a
  // jump in porosity a uniformly filled pore space then gives the donor's own
  // q, the upwind volume the pressure equation balances (an unlimited q would
  // be reconstructed up the jump: a fluid flowing along a staircase of
  // half-filled cells carries more mass than volume into the open cells
  // beside it, whose pressure then climbs step after step). With every n = 1
  // this is the plain scheme, bit for bit.
  void advance(const FaceField<Dim>& face_velocity, double dt,
               std::span<const std::span<double>> fields, std::span<const double> porosity);

 private:
  void set_face_courant_numbers(const FaceField<Dim>& face_velocity, double dt);
  template <Limiter limiter>
  void advance_field(std::span<double> q);
  // The fluxes along x of one row (the first direction: change_ is set)
  // and along direction > 0 (change_ accumulates; along y each row's x
  // fluxes first); `last`: q += change_ as each cell row is complete.
  template <Limiter limiter>
  void add_row_fluxes(std::span<double> q, int row, bool last);
  template <Limiter limiter>
  void add_plane_fluxes(std::span<double> q, int direction, bool last);

  CellGrid<Dim> grid_;
  Limiter limiter_;
  // Per face, the signed Courant number U dt / dx_d of the current step.
  FaceField<Dim> courant_;
  // Row buffers: the limited differences and the fluxes q_face U dt / dx_d
  // of one row along x; along another direction those of two cell rows and
  // two face rows.
  std::vector<double> row_difference_;
  std::vector<double> row_flux_;
  std::vector<double> difference_;
  std::vector<double> flux_;
  // Per cell, the net inflow over the step per unit volume.
  std::vector<double> change_;
  // The current field's reconstructed values: the field itself, or q / n in
  // per_pore_volume_ when pores_ (the porosity) is set for this call.
  const double* profile_ = nullptr;
  const double* pores_ = nullptr;
  std::vector<double> per_pore_volume_;
};

extern template class Advector<1>;
extern template class Advector<2>;
extern template class Advector<3>;

}  // namespace ice
