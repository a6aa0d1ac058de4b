#pragma once

// The block kernels of the stage, included by block_kernels.cpp (baseline
// instruction set), block_kernels_avx2.cpp and block_kernels_avx512.cpp:
// same source, same operations, so the same results bitwise. Internal
// linkage, and `flatten` inlines every helper into the kernel, so no
// out-of-line helper compiled for AVX2 or AVX-512 can be picked by the
// linker for the baseline.

#include <algorithm>
#include <cmath>

#include "solver_1d/block_kernel.hpp"
#include "solver_1d/branch_free_flux.hpp"
#include "solver_1d/branch_free_slope.hpp"
#include "swe/numerics/hydrostatic_reconstruction.hpp"
#include "swe/numerics/riemann_solvers.hpp"

namespace swe::solver_1d {
namespace {

// Advances interior cells [first, last). Local index j covers the cells
// first - 2 ... last + 1 (ghost-shifted index k = first + j). Each pass over
// the block is one branch-free loop (selects instead of early returns), so
// it vectorises.
template <FluxKind flux, LimiterKind limiter>
__attribute__((flatten)) void advance_block(const StageContext& c, std::size_t first,
                                            std::size_t last, double* work) {
  const std::size_t m = last - first + 2 * ghost_layers;
  const double g = c.g, dry_depth = c.dry_depth, sqrt_g = std::sqrt(c.g);
  const double* __restrict h = c.a.h_in + first;
  const double* __restrict q = c.a.q_in + first;
  const double* __restrict bed = c.a.bed + first;
  const double* __restrict half_width = c.cells->half_width.data() + first;
  const double* __restrict inv_width = c.cells->inv_width.data() + first;
  const double* __restrict inv_distance = c.cells->inv_centre_distance.data() + first;

  double* __restrict u = work;
  double* __restrict eta = u + m;
  double* __restrict h_minus = eta + m;
  double* __restrict h_plus = h_minus + m;
  double* __restrict bed_minus = h_plus + m;
  double* __restrict bed_plus = bed_minus + m;
  double* __restrict u_minus = bed_plus + m;
  double* __restrict u_plus = u_minus + m;
  double* __restrict bed_source = u_plus + m;
  double* __restrict mass = bed_source + m;
  double* __restrict momentum_left = mass + m;            // face j | j+1: the flux cell j sees
  double* __restrict momentum_right = momentum_left + m;  // ... the flux cell j+1 sees
  double* __restrict face_h_left = momentum_right + m;    // face j | j+1: hydrostatic depths
  double* __restrict face_h_right = face_h_left + m;
  double* __restrict roe_plain = face_h_right + m;  // 1 where Roe's plain formula holds

#pragma omp simd
  for (std::size_t j = 0; j < m; ++j) {
    const double velocity = q[j] / h[j];
    u[j] = h[j] >= dry_depth ? velocity : 0.0;
    eta[j] = h[j] + bed[j];
  }

  // MUSCL (van Leer, J. Comput. Phys. 32, 1979) on the non-uniform spacing:
  // limited slopes of h, eta and u per cell; the face beds follow from eta
  // and h, so a flat surface stays flat.
#pragma omp simd
  for (std::size_t j = 1; j < m - 1; ++j) {
    const double il = inv_distance[j - 1], ir = inv_distance[j], hw = half_width[j];
    const double dh = face_increment<limiter>(h[j] - h[j - 1], h[j + 1] - h[j], il, ir, hw);
    const double de = face_increment<limiter>(eta[j] - eta[j - 1], eta[j + 1] - eta[j], il, ir, hw);
    const double du = face_increment<limiter>(u[j] - u[j - 1], u[j + 1] - u[j], il, ir, hw);
    h_minus[j] = h[j] - dh;
    h_plus[j] = h[j] + dh;
    bed_minus[j] = (eta[j] - de) - h_minus[j];
    bed_plus[j] = (eta[j] + de) - h_plus[j];
    u_minus[j] = u[j] - du;
    u_plus[j] = u[j] + du;
    bed_source[j] = cell_bed_source(h_minus[j], bed_minus[j], h_plus[j], bed_plus[j], g);
  }

  // Faces j | j+1: the hydrostatic reconstruction (Audusse et al., SIAM J.
  // Sci. Comput. 25, 2004) measures both depths from the higher face bed; the pressure it removes
  // comes back as each side's correction. With the in-cell bed_source this is our form of the
  // well-balanced source split of Zheng et al., eqs. 33-34: a lake at rest,
  // dry emerged cells included, stays at rest and depths stay >= 0. (Two
  // loops: with the depths' max(0, .) in sight GCC 12 folds the flux's dry
  // tests into selects of booleans it cannot vectorise.)
#pragma omp simd
  for (std::size_t j = 1; j < m - 2; ++j) {
    const auto [hl, hr, left_correction, right_correction] =
        hydrostatic_face(h_plus[j], bed_plus[j], h_minus[j + 1], bed_minus[j + 1], g);
    face_h_left[j] = hl;
    face_h_right[j] = hr;
    momentum_left[j] = left_correction;
    momentum_right[j] = right_correction;
  }
  if constexpr (flux == FluxKind::roe) {
#pragma omp simd
    for (std::size_t j = 1; j < m - 2; ++j) {
      const auto [face_mass, face_momentum, plain] =
          plain_roe_flux_1d(face_h_left[j], u_plus[j], face_h_right[j], u_minus[j + 1], g, sqrt_g);
      mass[j] = face_mass;
      momentum_left[j] += face_momentum;
      momentum_right[j] += face_momentum;
      roe_plain[j] = plain;
    }
    // The few faces with a dry side or a transonic rarefaction.
    for (std::size_t j = 1; j < m - 2; ++j) {
      if (roe_plain[j] != 0.0) continue;
      const HydrostaticFace face =
          hydrostatic_face(h_plus[j], bed_plus[j], h_minus[j + 1], bed_minus[j + 1], g);
      const FaceFlux f = roe_flux(FaceState{face.h_left, u_plus[j], 0.0},
                                  FaceState{face.h_right, u_minus[j + 1], 0.0}, g);
      mass[j] = f.mass;
      momentum_left[j] = f.normal_momentum + face.left_correction;
      momentum_right[j] = f.normal_momentum + face.right_correction;
    }
  } else {
#pragma omp simd
    for (std::size_t j = 1; j < m - 2; ++j) {
      const auto [face_mass, face_momentum] =
          face_flux_1d<flux>(face_h_left[j], u_plus[j], face_h_right[j], u_minus[j + 1], g, sqrt_g);
      mass[j] = face_mass;
      momentum_left[j] += face_momentum;
      momentum_right[j] += face_momentum;
    }
  }
  if (first == 0 && c.imposed.left) mass[1] = c.imposed.left_value;
  if (last == c.cells->count && c.imposed.right) mass[m - 3] = c.imposed.right_value;

  // Zheng et al., eq. 28, combined into the SSP-RK2 stage
  //   U_out = wb U_base + (1 - wb) (U + dt L(U))   (Gottlieb & Shu, 1998).
  const double wb = c.base_weight, wi = 1.0 - c.base_weight, dt = c.dt;
  const double* h_base = c.a.h_base + first;  // may alias h_out
  const double* q_base = c.a.q_base + first;
  double* h_out = c.a.h_out + first;
  double* q_out = c.a.q_out + first;
#pragma omp simd
  for (std::size_t j = ghost_layers; j < m - ghost_layers; ++j) {
    const double dh_dt = -(mass[j] - mass[j - 1]) * inv_width[j];
    const double dq_dt =
        (bed_source[j] - (momentum_left[j] - momentum_right[j - 1])) * inv_width[j];
    const double h_new = std::max(0.0, wb * h_base[j] + wi * (h[j] + dt * dh_dt));
    const double q_new = wb * q_base[j] + wi * (q[j] + dt * dq_dt);
    h_out[j] = h_new;
    q_out[j] = h_new >= dry_depth ? q_new : 0.0;
  }
}

template <FluxKind flux>
BlockKernel select_block_kernel(LimiterKind limiter) {
  switch (limiter) {
    case LimiterKind::none:
      return &advance_block<flux, LimiterKind::none>;
    case LimiterKind::minmod:
      return &advance_block<flux, LimiterKind::minmod>;
    case LimiterKind::van_leer:
      return &advance_block<flux, LimiterKind::van_leer>;
    case LimiterKind::monotonized_central:
      return &advance_block<flux, LimiterKind::monotonized_central>;
  }
  return &advance_block<flux, LimiterKind::van_leer>;
}

BlockKernel select_block_kernel(FluxKind flux, LimiterKind limiter) {
  switch (flux) {
    case FluxKind::roe:
      return select_block_kernel<FluxKind::roe>(limiter);
    case FluxKind::hll:
      return select_block_kernel<FluxKind::hll>(limiter);
    case FluxKind::hllc:
      break;
  }
  return select_block_kernel<FluxKind::hllc>(limiter);
}

}  // namespace
}  // namespace swe::solver_1d
