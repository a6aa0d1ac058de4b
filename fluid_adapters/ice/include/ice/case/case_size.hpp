#pragma once

#include "cosim/config/node.hpp"
#include "cosim/io/run_size.hpp"

namespace ice {

// The size of an ICE run of `cells` cells in `dimension` (1 to 3) with
// `materials` fluids, and its memory as measured on the solver; the cells'
// key is `grid.cells`.
cosim::RunSize run_size(int dimension, double cells, int materials,
                        const cosim::config::Node& case_root);

}  // namespace ice
