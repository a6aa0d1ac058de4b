#pragma once

#include "cosim/mesh.hpp"
#include "mapping/constraint.hpp"
#include "mapping/operator.hpp"

namespace cosim::mapping::detail {

// Point or cell cloud ↔ uniform grid of the same dimension, with partition-of-
// unity kernel weights renormalised per cloud element (see build_operator.hpp).
// Exactly one of `from` and `to` is a cloud, the other a uniform grid.
Operator build_kernel_operator(const Mesh& from, const Mesh& to, Constraint constraint,
                               Kernel kernel);

}  // namespace cosim::mapping::detail
