#include "solver_1d/flux_stage.hpp"

#include <algorithm>
#include <cmath>

#include <omp.h>

#include "solver_1d/block_kernel.hpp"

namespace swe::solver_1d {

namespace {

// Below this many cells one thread does the stage.
constexpr std::size_t parallel_cells = 8192;

BlockKernel block_kernel(FluxKind flux, LimiterKind limiter) {
#ifdef SWE_1D_AVX2_KERNELS
  if (__builtin_cpu_supports("avx2")) return block_kernel_avx2(flux, limiter);
#endif
  return block_kernel_baseline(flux, limiter);
}

}  // namespace

void advance_stage(const LineCells& cells, const Physics& physics, const Scheme& scheme, const StageArrays& a,
                   const ImposedMassFlux& imposed, double base_weight, double dt,
                   std::vector<StageScratch>& scratch) {
  const std::size_t n = cells.count;
  const auto threads = static_cast<std::size_t>(omp_get_max_threads());
  if (scratch.size() < threads) scratch.resize(threads);
  const StageContext context{&cells, a, imposed, physics.gravity, physics.dry_depth, base_weight, dt};
  const BlockKernel kernel = block_kernel(scheme.flux, scheme.limiter);
  const auto blocks = static_cast<std::ptrdiff_t>((n + block_cells - 1) / block_cells);

#pragma omp parallel if (n >= parallel_cells)
  {
    std::vector<double>& work = scratch[static_cast<std::size_t>(omp_get_thread_num())].storage;
    work.resize(scratch_arrays * (block_cells + 2 * ghost_layers));
#pragma omp for schedule(static)
    for (std::ptrdiff_t b = 0; b < blocks; ++b) {
      const std::size_t first = static_cast<std::size_t>(b) * block_cells;
      kernel(context, first, std::min(n, first + block_cells), work.data());
    }
  }
}

}  // namespace swe::solver_1d
