#pragma once

#include "cosim/config/node.hpp"
#include "cosim/io/run_size.hpp"

namespace swe {

// The size of a shallow-water run of `cells` cells in `dimension` (1 or 2)
// and its memory as measured on the solver; the cells' key is `mesh`.
cosim::RunSize run_size(int dimension, double cells, const cosim::config::Node& case_root);

}  // namespace swe
