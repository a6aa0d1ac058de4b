#pragma once

#include "cosim/participant.hpp"
#include "mpm/io/run_driver.hpp"

namespace mpm {

// A run of a `kind: depth_averaged_case` file (options.config), standalone
// or, with an endpoint from `cosim run`, coupled to a two-phase swe_fluid
// (depth_averaged_coupling.hpp),
// as architecture.md §6 has every run: prepares <output>, log.txt, then
// writes
//   points.xdmf + points_<n>.h5   the points (velocity, depth, damage,
//                                 cohesion, structured share, mass),
//   ground.xdmf + ground_<n>.h5   cell-centred fields over the grid: the
//                                 solid depth, the bed, the mass's surface
//                                 and, in a lake, the fluid's surface
//                                 (heights above the reference plane),
//   gauges.csv                    depth and speed at each gauge,
//   summary.json                  mass and momentum at the start and end,
//                                 the front, tail and centre of the mass.
// Returns the exit code: 0, 2 bad input, 4 numerical failure (a point
// leaving the grid), 1 internal error.
int run_depth_averaged_case(const RunOptions& options,
                            const cosim::CouplingEndpoint& endpoint = {});

}  // namespace mpm
