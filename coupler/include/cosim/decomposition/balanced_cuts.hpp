#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace cosim::decomposition {

// Where to cut a line of slabs (e.g. the grid's columns of cells along x,
// weighted by the particles in each) into `parts` contiguous parts of weight
// as even as possible: the load balance of issue 27, which moves a
// Cartesian decomposition's cut planes by particle count. Returns parts + 1
// slab indices, 0 first and weights.size() last; part p is [cuts[p],
// cuts[p + 1]) and holds at least `min_slabs` slabs (the halo a part needs).
// Each cut lies at the slab boundary nearest the even share of the weight
// before it, within what the other parts' minimum leaves. Without weight
// (all zero) the slabs are split evenly. Throws std::invalid_argument for
// negative or non-finite weights, parts < 1, or fewer than parts x
// min_slabs slabs.
std::vector<std::int64_t> balanced_cuts(std::span<const double> weights, int parts,
                                        std::int64_t min_slabs = 1);

// The largest part's weight over the mean part's (1 is perfect balance; 0
// without weight).
double imbalance(std::span<const double> weights, std::span<const std::int64_t> cuts);

}  // namespace cosim::decomposition
