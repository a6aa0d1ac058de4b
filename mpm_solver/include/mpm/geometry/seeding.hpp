#pragma once

#include <functional>

#include "mpm/core/tensor.hpp"
#include "mpm/geometry/box.hpp"
#include "mpm/geometry/seeded_particles.hpp"
#include "mpm/shape/grid_geometry.hpp"

// How a region becomes particles: candidate points are placed cell by cell
// on the background grid and kept when the region holds them; each particle
// gets the cell volume divided by the points per cell.
namespace mpm {

struct SeedingPattern {
  enum class Kind {
    regular,       // per_direction^Dim points at the centres of equal sub-cells
    quasi_random,  // per_cell points of the R_d sequence (van den Bout et al., eq. 88)
  };
  Kind kind = Kind::regular;
  int per_direction = 2;  // regular; also sets per_cell = per_direction^Dim when per_cell is 0
  int per_cell = 0;       // quasi_random
};

// Points per cell for `pattern` in Dim dimensions; throws cosim::InputError
// unless it is at least 1.
template <int Dim>
int points_per_cell(const SeedingPattern& pattern);

// Relative positions in [0, 1)^Dim of the points of one cell, the same for
// every cell (so seeding is deterministic and translation invariant).
//   regular: ((i + 1/2) / n, (j + 1/2) / n, ...), x fastest;
//   quasi_random: x_k = frac(k alpha), k = 1..per_cell, with
//   alpha = (1/phi, 1/phi^2[, 1/phi^3]) and phi the real root of
//   x^(Dim+1) = x + 1 (the plastic constant 1.3247179572 in 2D, eq. 88;
//   the generalised R_d sequence of Roberts in 3D).
template <int Dim>
std::vector<Vec<Dim>> cell_pattern(const SeedingPattern& pattern);

// phi_d: the real root > 1 of x^(d+1) = x + 1.
double r_sequence_root(int d);

// Seeds the points of every grid cell that the region's bounding box
// touches and keeps those `inside` holds. Volume per particle: cell volume /
// points per cell; half-length per direction: spacing / (2 n^(1/Dim)) with n
// the points per cell (spacing / (2 per_direction) for regular seeding).
template <int Dim>
SeededParticles<Dim> seed_cells(const std::function<bool(const Vec<Dim>&)>& inside,
                                const Box<Dim>& bounds, const GridGeometry<Dim>& grid,
                                const SeedingPattern& pattern);

// The same for any region with contains(x) and bounding_box() (Box,
// Polygon, Polyhedron).
template <int Dim, class Region>
SeededParticles<Dim> seed_region(const Region& region, const GridGeometry<Dim>& grid,
                                 const SeedingPattern& pattern) {
  return seed_cells<Dim>([&region](const Vec<Dim>& x) { return region.contains(x); },
                         region.bounding_box(), grid, pattern);
}

}  // namespace mpm
