#pragma once

#include "cosim/config/node.hpp"
#include "cosim/io/run_size.hpp"
#include "mpm/case/case_description.hpp"

// The size of an MPM run: its particles and its grid's values (one set per
// velocity field), with the memory each takes as measured on the solver.
namespace mpm::case_loading {

// What fixes the size of a case apart from its particles.
struct GridDemand {
  int dimension = 2;
  GridSpec grid;
  ShapeKind shape = ShapeKind::gimp;
  int velocity_fields = 1;  // one per body in grid contact, else one shared plus one per rigid body
};

// The velocity fields the solver will allocate for the case's bodies and
// contact (see Solver: contact gives every body its own).
int velocity_fields(const cosim::config::Node& case_root);

// The run's size with `particles` particles; the particles' key is the case's
// `bodies`, the grid's `grid.cells`.
cosim::RunSize run_size(const GridDemand& demand, double particles,
                        const cosim::config::Node& case_root);

}  // namespace mpm::case_loading
