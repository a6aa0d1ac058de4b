#pragma once

#include <algorithm>
#include <cstddef>

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

// A cell's MUSCL reconstruction along one direction: the states at its lower
// and upper faces in the face frame, and the bed there (eta_face - h_face).
struct ReconstructedCell {
  FaceState lower, upper;
  double bed_lower = 0.0, bed_upper = 0.0;
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
// +-stride: limited slopes (undivided, uniform spacing) of h, eta = h + B and
// the two velocity components; the face bed follows from eta and h so a
// flat surface stays flat.
template <LimiterKind limiter>
inline void reconstruct_cells(PrimitiveView p, const double* un, const double* ut, std::ptrdiff_t first,
                              std::ptrdiff_t count, std::ptrdiff_t stride, ReconstructedCell* out) {
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::ptrdiff_t c = first + k;
    auto half_slope = [&](const double* q) {
      return 0.5 * limited_slope(limiter, q[c] - q[c - stride], q[c + stride] - q[c]);
    };
    const double dh = half_slope(p.h), deta = half_slope(p.eta);
    const double dun = half_slope(un), dut = half_slope(ut);
    ReconstructedCell& r = out[k];
    r.lower.h = std::max(0.0, p.h[c] - dh);
    r.upper.h = std::max(0.0, p.h[c] + dh);
    r.bed_lower = (p.eta[c] - deta) - r.lower.h;
    r.bed_upper = (p.eta[c] + deta) - r.upper.h;
    r.lower.un = un[c] - dun;
    r.upper.un = un[c] + dun;
    r.lower.ut = ut[c] - dut;
    r.upper.ut = ut[c] + dut;
  }
}

// Flux through the face between `lower` (its upper face) and `upper` (its
// lower face): hydrostatic reconstruction, then the Riemann solver.
template <FluxKind flux>
inline FaceFluxes face_fluxes(const ReconstructedCell& lower, const ReconstructedCell& upper, double g) {
  const HydrostaticFace hr = hydrostatic_face(lower.upper.h, lower.bed_upper, upper.lower.h, upper.bed_lower, g);
  const FaceFlux f = numerical_flux(flux, FaceState{hr.h_left, lower.upper.un, lower.upper.ut},
                                    FaceState{hr.h_right, upper.lower.un, upper.lower.ut}, g);
  return {f.mass, f.normal_momentum + hr.left_correction, f.normal_momentum + hr.right_correction,
          f.tangential_momentum};
}

// Fluxes of `count` faces, face k between cells lower[k] and upper[k].
template <FluxKind flux>
inline void face_fluxes(const ReconstructedCell* lower, const ReconstructedCell* upper, std::ptrdiff_t count, double g,
                        FaceFluxes* out) {
  for (std::ptrdiff_t k = 0; k < count; ++k) out[k] = face_fluxes<flux>(lower[k], upper[k], g);
}

// Flux difference across a cell minus its in-cell bed source, per unit
// length of the direction (inv_spacing = 1 / dx or 1 / dy).
inline DirectionalResidual residual(const FaceFluxes& lower_face, const FaceFluxes& upper_face,
                                    const ReconstructedCell& cell, double inv_spacing, double g) {
  const double bed_source = cell_bed_source(cell.lower.h, cell.bed_lower, cell.upper.h, cell.bed_upper, g);
  return {(upper_face.mass - lower_face.mass) * inv_spacing,
          (upper_face.normal_momentum_to_lower - lower_face.normal_momentum_to_upper - bed_source) * inv_spacing,
          (upper_face.tangential_momentum - lower_face.tangential_momentum) * inv_spacing};
}

}  // namespace swe::solver_2d
