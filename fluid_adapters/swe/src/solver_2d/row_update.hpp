#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "solver_2d/directional_sweep.hpp"
#include "swe/numerics/manning_friction.hpp"

namespace swe::solver_2d {

// Everything the update of one row of cells reads and writes; pointers
// address the row's first interior cell (faces: its lower face).
struct RowUpdate {
  const FaceFluxes* x_faces;  // nx + 1 faces
  const FaceFluxes* y_faces_below;
  const FaceFluxes* y_faces_above;
  FaceSides x_cells;  // from the row's first interior cell
  FaceSides y_cells;
  const double *in_h, *in_hu, *in_hv;
  const double *base_h, *base_hu, *base_hv;
  const double* bed;
  double *out_h, *out_hu, *out_hv, *out_eta, *out_u, *out_v;
};

struct UpdateConstants {
  double dt, inv_dx, inv_dy, base_weight, gravity, dry_depth, manning;
};

// The SSP-RK2 stage update of nx cells (see runge_kutta_stage), then the
// friction and the primitives, each as its own loop over the row so the
// first and last vectorise.
template <bool with_friction>
SWE_2D_ROW_LOOP void update_row(const RowUpdate& r, std::ptrdiff_t nx, const UpdateConstants& k) {
  const double g = k.gravity, dt = k.dt, base_weight = k.base_weight,
               stage_weight = 1.0 - k.base_weight;
  const double dry_depth = k.dry_depth;
#pragma omp simd
  for (std::ptrdiff_t i = 0; i < nx; ++i) {
    const DirectionalResidual rx =
        residual(r.x_faces[i], r.x_faces[i + 1], r.x_cells, i, k.inv_dx, g);
    const DirectionalResidual ry =
        residual(r.y_faces_below[i], r.y_faces_above[i], r.y_cells, i, k.inv_dy, g);
    const double h = std::max(
        base_weight * r.base_h[i] + stage_weight * (r.in_h[i] - dt * (rx.mass + ry.mass)), 0.0);
    const double hu =
        base_weight * r.base_hu[i] +
        stage_weight * (r.in_hu[i] - dt * (rx.normal_momentum + ry.tangential_momentum));
    const double hv =
        base_weight * r.base_hv[i] +
        stage_weight * (r.in_hv[i] - dt * (rx.tangential_momentum + ry.normal_momentum));
    const bool wet = h >= dry_depth;  // dry cells carry no momentum
    r.out_h[i] = h;
    r.out_hu[i] = wet ? hu : 0.0;
    r.out_hv[i] = wet ? hv : 0.0;
  }
  if constexpr (with_friction) {
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      const double h = r.out_h[i];
      if (h < dry_depth) continue;
      const double hu = r.out_hu[i], hv = r.out_hv[i];
      const double factor = manning_factor(h, std::sqrt(hu * hu + hv * hv) / h, g, k.manning, dt);
      r.out_hu[i] = hu * factor;
      r.out_hv[i] = hv * factor;
    }
  }
  // update_primitives, vectorised.
#pragma omp simd
  for (std::ptrdiff_t i = 0; i < nx; ++i) {
    const double h = r.out_h[i];
    const double inv_h = 1.0 / h;
    const bool wet = h >= dry_depth;
    r.out_eta[i] = h + r.bed[i];
    r.out_u[i] = wet ? r.out_hu[i] * inv_h : 0.0;
    r.out_v[i] = wet ? r.out_hv[i] * inv_h : 0.0;
  }
}

}  // namespace swe::solver_2d
