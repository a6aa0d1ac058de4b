#pragma once

#include <cmath>
#include <limits>

#include "mpm/core/tensor.hpp"
#include "mpm/material/elastic_constants.hpp"

namespace mpm {

// The Mohr-Coulomb surface with a tension cut-off in principal stresses
// sorted sigma_1 >= sigma_2 >= sigma_3, tension positive. Tran et al.,
// MPMICE, eq. 16 with its sigma_1 (most compressive) named sigma_3 here:
//   f = (sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin phi - 2 c cos phi,
//   g = (sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin psi,
// (the cohesion term taken with the sign that makes f(0) = -2 c cos phi < 0),
// and the Rankine cut-off sigma_1 <= sigma_t, associated.
struct MohrCoulombSurface {
  double sin_friction = 0.0;                                          // sin phi
  double cos_friction = 1.0;                                          // cos phi
  double sin_dilation = 0.0;                                          // sin psi, psi <= phi
  double cohesion = 0.0;                                              // c [Pa]
  double tensile_strength = std::numeric_limits<double>::infinity();  // sigma_t [Pa]

  // From the angles phi and psi [rad].
  static MohrCoulombSurface from_angles(double friction_angle, double dilation_angle,
                                        double cohesion, double tensile_strength) {
    return {std::sin(friction_angle), std::cos(friction_angle), std::sin(dilation_angle), cohesion,
            tensile_strength};
  }

  // Hydrostatic stress of the apex, c cot phi (infinite for phi = 0).
  double apex() const {
    return sin_friction > 0.0 ? cohesion * cos_friction / sin_friction
                              : std::numeric_limits<double>::infinity();
  }
  // The cut-off acts only where it is below the apex.
  bool has_tension_cutoff() const { return tensile_strength < apex(); }

  // max(f, sigma_1 - sigma_t) at sorted principal stresses [Pa].
  double yield(const Vec3d& principal) const;
  // True when a (possibly unsorted) stress is inside both surfaces by a bound
  // from its invariants p and q = sqrt(J2), no eigenvalues needed:
  //   sigma_1 - sigma_3 <= 2q,  sigma_1 + sigma_3 <= 2p + q / sqrt 3,  sigma_1 <= p + 2q / sqrt 3.
  bool surely_inside(const Tensor& stress) const;
};

// The yield planes in sorted principal space that a return may end on:
// f of the pairs (1,3), (2,3), (1,2) of principal stresses and the cut-off
// on each principal stress. Plane (2,3) meets (1,3) on the triaxial
// compression edge sigma_1 = sigma_2; plane (1,2) meets it on the triaxial
// extension edge sigma_2 = sigma_3.
enum MohrCoulombPlane : unsigned {
  shear_13 = 1u << 0,
  shear_23 = 1u << 1,
  shear_12 = 1u << 2,
  tension_1 = 1u << 3,
  tension_2 = 1u << 4,
  tension_3 = 1u << 5,
};

struct PrincipalReturn {
  Vec3d stress;         // sorted principal stresses after the return
  unsigned active = 0;  // MohrCoulombPlane bits of the planes returned to; 0: elastic
};

// Return mapping of a sorted trial stress for perfect plasticity in one step
// (Clausen, Damkilde & Andersen 2006, 2007: planes, lines and points in
// principal space). With isotropic elasticity D the return is
//   sigma = sigma_trial - sum_i dlambda_i D b_i,  b_i = dg_i/dsigma,
// over a set of active planes solved for f_i(sigma) = 0. The set is the first
// of: one plane, a line (compression edge, extension edge, shear-tension,
// tension-tension), a point (Mohr-Coulomb apex, or with the cut-off its
// corners) for which all dlambda_i >= 0 and no plane is violated; these are
// the Kuhn-Tucker conditions, which bound the return regions. What no plane
// or edge takes goes to the apex (for psi < phi the apex return is not a
// combination of the potentials' gradients; with psi = 0 they have no
// volumetric part at all).
PrincipalReturn mohr_coulomb_return(const Vec3d& trial, const MohrCoulombSurface& surface,
                                    const ElasticConstants& elastic);

}  // namespace mpm
