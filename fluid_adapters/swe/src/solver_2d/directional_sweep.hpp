#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "solver_2d/hllc_selects.hpp"
#include "solver_2d/row_loop.hpp"
#include "swe/numerics/face_state.hpp"
#include "swe/numerics/hydrostatic_reconstruction.hpp"
#include "swe/numerics/riemann_solvers.hpp"
#include "swe/numerics/slope_limiter.hpp"
#include "swe/scheme.hpp"

// The pieces of one direction of the 2D scheme, written once for both: the
// caller hands in the stride between neighbours along the direction and the
// velocity arrays in the face's order (normal, tangential). x sweeps pass
// (1, u, v), y sweeps (row stride, v, u); everything below is the same code,
// so a state symmetric under x <-> y is advanced symmetrically.
namespace swe::solver_2d {

// MUSCL reconstructions (van Leer, J. Comput. Phys. 32, 1979) of a run of
// cells along one direction (SoA, so the loops vectorise): the states at each
// cell's lower and upper faces in the face frame, and the bed there
// (eta_face - h_face).
struct ReconstructedCells {
  std::vector<double> h_lower, h_upper, bed_lower, bed_upper;
  std::vector<double> un_lower, un_upper, ut_lower, ut_upper;

  void resize(std::ptrdiff_t n) {
    for (auto* v :
         {&h_lower, &h_upper, &bed_lower, &bed_upper, &un_lower, &un_upper, &ut_lower, &ut_upper})
      v->resize(n);
  }
};

// Fluxes through one face per unit face length. The normal momentum flux
// carries the hydrostatic-reconstruction pressure correction of the side
// that receives it (Audusse et al., 2004).
struct FaceFluxes {
  double mass = 0.0;
  double normal_momentum_to_lower = 0.0;  // seen by the cell below/left of the face
  double normal_momentum_to_upper = 0.0;  // seen by the cell above/right of the face
  double tangential_momentum = 0.0;
};

// d/dt of (h, h u_n, h u_t) of a cell from one direction, with the sign of a
// divergence: U_t = -(R_x + R_y).
struct DirectionalResidual {
  double mass = 0.0, normal_momentum = 0.0, tangential_momentum = 0.0;
};

// Read-only primitives of the padded cells.
struct PrimitiveView {
  const double* h;
  const double* eta;
};

// Reconstructs `count` cells, first, first + 1, ..., with neighbours at
// +-stride, into out[0 .. count): limited slopes (undivided, uniform spacing)
// of h, eta = h + B and the two velocity components; the face bed follows
// from eta and h so a flat surface stays flat.
template <LimiterKind limiter>
SWE_2D_ROW_LOOP void reconstruct_cells(PrimitiveView p, const double* un, const double* ut,
                                       std::ptrdiff_t first, std::ptrdiff_t count,
                                       std::ptrdiff_t stride, ReconstructedCells& out) {
  const double* h = p.h + first;
  const double* eta = p.eta + first;
  un += first;
  ut += first;
  double* __restrict h_lower = out.h_lower.data();
  double* __restrict h_upper = out.h_upper.data();
  double* __restrict bed_lower = out.bed_lower.data();
  double* __restrict bed_upper = out.bed_upper.data();
  double* __restrict un_lower = out.un_lower.data();
  double* __restrict un_upper = out.un_upper.data();
  double* __restrict ut_lower = out.ut_lower.data();
  double* __restrict ut_upper = out.ut_upper.data();
#pragma omp simd
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::ptrdiff_t below = k - stride, above = k + stride;
    const double dh = 0.5 * swe::limited_slope<limiter>(h[k] - h[below], h[above] - h[k]);
    const double deta = 0.5 * swe::limited_slope<limiter>(eta[k] - eta[below], eta[above] - eta[k]);
    const double dun = 0.5 * swe::limited_slope<limiter>(un[k] - un[below], un[above] - un[k]);
    const double dut = 0.5 * swe::limited_slope<limiter>(ut[k] - ut[below], ut[above] - ut[k]);
    h_lower[k] = std::max(0.0, h[k] - dh);
    h_upper[k] = std::max(0.0, h[k] + dh);
    bed_lower[k] = (eta[k] - deta) - h_lower[k];
    bed_upper[k] = (eta[k] + deta) - h_upper[k];
    un_lower[k] = un[k] - dun;
    un_upper[k] = un[k] + dun;
    ut_lower[k] = ut[k] - dut;
    ut_upper[k] = ut[k] + dut;
  }
}

// The faces of a run of reconstructed cells, as raw pointers (so the face
// loop reads them without reloading the vectors).
struct FaceSides {
  const double *h_lower, *h_upper, *bed_lower, *bed_upper, *un_lower, *un_upper, *ut_lower,
      *ut_upper;

  explicit FaceSides(const ReconstructedCells& c, std::ptrdiff_t first)
      : h_lower(c.h_lower.data() + first),
        h_upper(c.h_upper.data() + first),
        bed_lower(c.bed_lower.data() + first),
        bed_upper(c.bed_upper.data() + first),
        un_lower(c.un_lower.data() + first),
        un_upper(c.un_upper.data() + first),
        ut_lower(c.ut_lower.data() + first),
        ut_upper(c.ut_upper.data() + first) {}
};

// Flux through the face between cell k of `lower` (its upper face) and cell
// k of `upper` (its lower face): hydrostatic reconstruction, then the
// Riemann solver.
template <FluxKind flux>
inline FaceFluxes face_fluxes(const FaceSides& lower, const FaceSides& upper, std::ptrdiff_t k,
                              double g) {
  const HydrostaticFace hr = hydrostatic_face(lower.h_upper[k], lower.bed_upper[k],
                                              upper.h_lower[k], upper.bed_lower[k], g);
  const FaceState left{hr.h_left, lower.un_upper[k], lower.ut_upper[k]};
  const FaceState right{hr.h_right, upper.un_lower[k], upper.ut_lower[k]};
  const FaceFlux f = flux == FluxKind::hllc ? hllc_flux_selects(left, right, g)
                                            : numerical_flux(flux, left, right, g);
  return {f.mass, f.normal_momentum + hr.left_correction, f.normal_momentum + hr.right_correction,
          f.tangential_momentum};
}

// Fluxes of `count` faces, face k between cells lower_first + k of `lower`
// and upper_first + k of `upper`.
template <FluxKind flux>
SWE_2D_ROW_LOOP [[gnu::flatten]] void face_fluxes(const ReconstructedCells& lower,
                                                  std::ptrdiff_t lower_first,
                                                  const ReconstructedCells& upper,
                                                  std::ptrdiff_t upper_first, std::ptrdiff_t count,
                                                  double g, FaceFluxes* out) {
  const FaceSides l(lower, lower_first), u(upper, upper_first);
#pragma omp simd
  for (std::ptrdiff_t k = 0; k < count; ++k) out[k] = face_fluxes<flux>(l, u, k, g);
}

// Flux difference across a cell minus its in-cell bed source, per unit
// length of the direction (inv_spacing = 1 / dx or 1 / dy).
inline DirectionalResidual residual(const FaceFluxes& lower_face, const FaceFluxes& upper_face,
                                    const FaceSides& cells, std::ptrdiff_t k, double inv_spacing,
                                    double g) {
  const double bed_source = cell_bed_source(cells.h_lower[k], cells.bed_lower[k], cells.h_upper[k],
                                            cells.bed_upper[k], g);
  return {(upper_face.mass - lower_face.mass) * inv_spacing,
          (upper_face.normal_momentum_to_lower - lower_face.normal_momentum_to_upper - bed_source) *
              inv_spacing,
          (upper_face.tangential_momentum - lower_face.tangential_momentum) * inv_spacing};
}

}  // namespace swe::solver_2d
