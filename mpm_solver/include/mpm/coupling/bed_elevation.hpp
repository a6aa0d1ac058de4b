#pragma once

#include <vector>

#include "mpm/coupling/body_roles.hpp"
#include "mpm/coupling/over_ranks.hpp"
#include "mpm/coupling/surface_grid.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::coupling {

// The bed B per surface cell for the shallow-water solver (Zheng et al.,
// Sec. 2 and Algorithm 1, line 15), from the top envelope of the bed
// particles: each particle is a plateau of height z_p + l_p over its
// horizontal domain [x_p - l_p, x_p + l_p]; the envelope E(x) is the
// highest plateau above x (the grid bottom where none is), and
//   B_c = (1 / |c|) integral over cell c of E(x) dx,
// the cell average a finite-volume scheme wants. The integral is exact
// along x (the envelope is piecewise constant), so B moves continuously as
// particles move and does not jump when a particle crosses a cell edge. In
// 3D it is averaged over `strips` lines across each cell in y (a particle
// entering a strip changes B by at most its height difference / strips).
// On a rank of a decomposed MPM the envelope is that of every rank's points
// (`gather_over_ranks`: the plateaus not hidden on their own rank).
template <int Dim>
std::vector<double> bed_elevation(const SurfaceGrid<Dim>& surface, const Particles<Dim>& particles,
                                  const std::vector<BodyRole>& roles, int strips,
                                  const GatherOverRanks& gather_over_ranks = {});

}  // namespace mpm::coupling
