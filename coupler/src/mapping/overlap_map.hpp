#pragma once

#include "cosim/mesh.hpp"
#include "mapping/constraint.hpp"
#include "mapping/operator.hpp"

namespace cosim::mapping::detail {

// Uniform grids and non-uniform lines ↔ each other, from exact overlap
// volumes of their control volumes (see build_operator.hpp). Both meshes are
// structured with the same dimension.
Operator build_overlap_operator(const Mesh& from, const Mesh& to, Constraint constraint);

}  // namespace cosim::mapping::detail
