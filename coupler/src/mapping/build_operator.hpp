#pragma once

#include "cosim/mesh.hpp"
#include "mapping/constraint.hpp"
#include "mapping/operator.hpp"

namespace cosim::mapping {

// Builds the operator mapping values on `from` to values on `to`.
//
// Supported pairs (dimensions must match):
//   uniform grid / non-uniform line ↔ uniform grid / non-uniform line (1D for lines):
//     exact overlap volumes of the control volumes (cells; for node-centred
//     grids the dual cells, halved at the boundary). Consistent rows are the
//     overlap-weighted average of the source; the conservative map A→B is the
//     transpose of the consistent map B→A.
//   point cloud / cell cloud ↔ uniform grid: kernel weights (Options::kernel)
//     renormalised per cloud element over the grid points that exist, so a
//     particle next to the boundary keeps its whole amount. grid→cloud
//     consistent is interpolation with these weights; cloud→grid consistent is
//     the kernel- and volume-weighted average; the conservative maps are the
//     transposes of the consistent maps of the reverse pair.
//   a point cloud / cell cloud ↔ the same cloud (equal positions and volumes,
//     e.g. a participant's mesh and the exchange on it): the identity.
//
// Elements with nothing to map:
//   conservative: a source element that overlaps no target element (or lies
//     beyond the kernel support of every grid point) goes whole to the nearest
//     target element (grids and lines: the clamped index in each direction;
//     grid→cloud: the cloud element found nearest in grid steps) and is counted
//     in Operator::fallback_source_count().
//   consistent: a target element that no source reaches gets 0 and is listed
//     in Operator::empty_target_indices(). A cloud element outside the grid
//     takes the value of the nearest grid point (clamped index).
//
// Throws InputError naming both meshes for an unsupported pair or mismatched
// dimensions, and for a mesh that fails cosim::validate().
Operator build_operator(const Mesh& from, const Mesh& to, Constraint constraint,
                        const Options& options = {});

}  // namespace cosim::mapping
