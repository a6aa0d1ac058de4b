#pragma once

#include <cstddef>

#include "solver_1d/flux_stage.hpp"
#include "solver_1d/line_cells.hpp"
#include "swe/scheme.hpp"

namespace swe::solver_1d {

// Cells per block: the block's work arrays stay in the core's cache.
inline constexpr std::size_t block_cells = 512;
inline constexpr std::size_t scratch_arrays = 15;

struct StageContext {
  const LineCells* cells;
  StageArrays a;
  ImposedMassFlux imposed;
  double g, dry_depth, base_weight, dt;
};

// Advances the interior cells [first, last) of one block; `work` holds
// scratch_arrays * (block_cells + 2 ghost_layers) values.
using BlockKernel = void (*)(const StageContext& c, std::size_t first, std::size_t last,
                             double* work);

// The kernel for a flux and limiter, for any x86-64 (SSE2) ...
BlockKernel block_kernel_baseline(FluxKind flux, LimiterKind limiter);
#ifdef SWE_1D_X86_KERNELS
// ... and for CPUs with AVX2 or AVX-512 (4 or 8 lanes; no FMA contraction,
// so the same results bitwise).
BlockKernel block_kernel_avx2(FluxKind flux, LimiterKind limiter);
BlockKernel block_kernel_avx512(FluxKind flux, LimiterKind limiter);
#endif

}  // namespace swe::solver_1d
