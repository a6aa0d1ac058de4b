#include "solver_1d/flux_stage.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "solver_1d/block_kernel.hpp"
#include "solver_1d/ghost_cells.hpp"

namespace swe::solver_1d {

namespace {

// Below this many cells one thread does the stage.
constexpr std::size_t parallel_cells = 8192;

BlockKernel block_kernel(FluxKind flux, LimiterKind limiter) {
#ifdef SWE_1D_X86_KERNELS
  if (__builtin_cpu_supports("avx512f")) return block_kernel_avx512(flux, limiter);
  if (__builtin_cpu_supports("avx2")) return block_kernel_avx2(flux, limiter);
#endif
  return block_kernel_baseline(flux, limiter);
}

}  // namespace

void advance_step(const LineCells& cells, const Physics& physics, const Scheme& scheme,
                  const Boundaries1d& boundaries, const StepArrays& a,
                  const ImposedMassFlux& imposed, double dt, std::vector<StageScratch>& scratch) {
  const std::size_t n = cells.count;
  const auto threads = static_cast<std::size_t>(omp_get_max_threads());
  if (scratch.size() < threads) scratch.resize(threads);
  // SSP-RK2 (Gottlieb & Shu, 1998). Stage 1: (h, q) -> stage; stage 2:
  // stage -> (h, q) with base (h, q).
  const StageContext first_stage{&cells,
                                 {a.h, a.q, a.bed, a.h, a.q, a.h_stage, a.q_stage},
                                 imposed,
                                 physics.gravity,
                                 physics.dry_depth,
                                 0.0,
                                 dt};
  const StageContext second_stage{&cells,
                                  {a.h_stage, a.q_stage, a.bed, a.h, a.q, a.h, a.q},
                                  imposed,
                                  physics.gravity,
                                  physics.dry_depth,
                                  0.5,
                                  dt};
  const BlockKernel kernel = block_kernel(scheme.flux, scheme.limiter);
  const std::size_t blocks = (n + block_cells - 1) / block_cells;
  auto run = [&](const StageContext& stage, std::size_t block, double* work) {
    const std::size_t first = block * block_cells;
    kernel(stage, first, std::min(n, first + block_cells), work);
  };

#pragma omp parallel if (n >= parallel_cells)
  {
    std::vector<double>& work = scratch[static_cast<std::size_t>(omp_get_thread_num())].storage;
    work.resize(scratch_arrays * (block_cells + 2 * ghost_layers));
    const auto team = static_cast<std::size_t>(omp_get_num_threads());
    const auto rank = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t begin = blocks * rank / team, end = blocks * (rank + 1) / team;
    // The blocks next to a neighbour's first take stage 1 before anyone
    // overwrites (h, q) in stage 2, and give the neighbours the stage values
    // their edge cells need.
    if (begin < end) run(first_stage, begin, work.data());
    if (begin + 1 < end) run(first_stage, end - 1, work.data());
#pragma omp barrier
#pragma omp single
    fill_ghost_cells(boundaries, physics, n, a.h_stage, a.q_stage);
    // Then one pass over the blocks: stage 1 of block b + 1 reads (h, q) of
    // block b before stage 2 of block b overwrites them, and stage 2 reads
    // the stage values while they are still in cache.
    for (std::size_t b = begin; b < end; ++b) {
      if (b + 2 < end) run(first_stage, b + 1, work.data());
      run(second_stage, b, work.data());
    }
  }
}

}  // namespace swe::solver_1d
