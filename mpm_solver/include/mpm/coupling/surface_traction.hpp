#pragma once

#include <span>
#include <vector>

#include "mpm/coupling/body_roles.hpp"
#include "mpm/coupling/over_ranks.hpp"
#include "mpm/coupling/surface_grid.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::coupling {

// Totals of one distribution [N] (per unit depth in 2D).
template <int Dim>
struct TractionTotals {
  Vec<Dim> received = Vec<Dim>::Zero();   // sum over cells of traction x cell area
  Vec<Dim> applied = Vec<Dim>::Zero();    // sum over the particles
  Vec<Dim> unapplied = Vec<Dim>::Zero();  // columns without deformable bed particles
  std::size_t surface_particles = 0;
};

// The water's traction on the bed (Zheng et al., eq. 10: hydrostatic
// pressure normal, Manning shear tangential; Algorithm 1, line 21) as
// surface traction on the bed's surface particles (Zheng et al., eq. 12).
// A particle belongs to the column holding its centre; the column's surface
// particles are its deformable bed particles whose domain top z_p + l_p lies
// less than one particle height 2 l_p below the column's highest top (the
// top layer; a regular layer below it is exactly 2 l_p lower and left out). Each
// column's force F_c = t_c A_c is split over them by their face area
// a_p = V0_p / (2 l_p) (as the solver's surface loads), so the forces sum
// to F_c exactly:
//   force[p] = F_c a_p / sum_q a_q.
// `traction` holds Dim components per surface cell (horizontal, then
// vertical) [Pa]. On a rank of a decomposed MPM the columns' highest tops
// and face areas are every rank's (`max_over_ranks`, `sum_over_ranks`), and
// each rank gives its own surface particles their forces (`applied` and
// `surface_particles` are then this rank's).
template <int Dim>
TractionTotals<Dim> surface_traction(const SurfaceGrid<Dim>& surface,
                                     std::span<const double> traction,
                                     const Particles<Dim>& particles,
                                     const std::vector<BodyRole>& roles,
                                     std::vector<Vec<Dim>>& force,
                                     const MaxOverRanks& max_over_ranks = {},
                                     const SumOverRanks& sum_over_ranks = {});

}  // namespace mpm::coupling
