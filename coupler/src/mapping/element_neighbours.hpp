#pragma once

#include <cstddef>
#include <vector>

#include "cosim/mesh.hpp"

namespace cosim::mapping::detail {

// Adjacency of a mesh's elements: neighbours of e are
// neighbour[start[e]] .. neighbour[start[e + 1] - 1].
struct ElementNeighbours {
  std::vector<std::size_t> start;
  std::vector<std::size_t> neighbour;
};

// Grids: face neighbours. Lines: the cells left and right. Clouds: the
// elements in the same and adjacent bins of a uniform binning whose bin size
// is the typical element size (mean volume)^(1/dim), enlarged so that there
// are at most about two bins per element.
ElementNeighbours element_neighbours(const Mesh& mesh);

}  // namespace cosim::mapping::detail
