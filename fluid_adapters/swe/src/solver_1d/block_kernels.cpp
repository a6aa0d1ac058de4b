#include "solver_1d/advance_block.hpp"

namespace swe::solver_1d {

BlockKernel block_kernel_baseline(FluxKind flux, LimiterKind limiter) {
  return select_block_kernel(flux, limiter);
}

}  // namespace swe::solver_1d
