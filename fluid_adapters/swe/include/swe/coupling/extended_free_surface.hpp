#pragma once

#include <span>
#include <vector>

#include "swe/solver.hpp"

namespace swe {

// The water's surface per cell of a 2D solver, defined everywhere: h + z_b
// on wet cells (h > dry depth), and on a dry cell the mean of its already
// reached neighbours' levels, reached outwards from the water one ring of
// cells at a time (the level of the nearest water, as a water table under
// dry ground). A mass that reads it is then submerged up to the lake's
// level where it stands out of the water, as in a lake at rest, and not at
// all where the ground rises above the water. With no wet cell at all it is
// `dry_level` (the ground without solids: nothing submerged).
// Throws std::invalid_argument for a 1D solver or a dry_level of another size.
std::vector<double> extended_free_surface(const Solver& solver, std::span<const double> dry_level);

}  // namespace swe
