#pragma once

#include "mpm/core/tensor.hpp"

namespace mpm {

// The depth-averaged in-plane stress of a column beyond its earth pressure
// (van den Bout et al., OpenLISEM Hazard, eq. 43's last term, (1/h) int
// sigma_xx dh, from the stress-strain relation of eqs. 22-23 as it applies in
// the plane): elastic in plane stress, rotated with the material (Jaumann),
// and bounded by Mohr-Coulomb on the total in-plane stress, the earth
// pressure included. Tension is positive.
struct InPlaneStress {
  double youngs_modulus = 0.0;  // E [Pa]; 0: no in-plane stress
  double poisson_ratio = 0.0;   // nu [-]

  bool enabled() const { return youngs_modulus > 0.0; }
  // The speed of in-plane elastic waves, sqrt(E / ((1 - nu^2) rho)) [m/s].
  double wave_speed(double density) const;

  // sigma advanced over dt with the velocity gradient L = grad v:
  // sigma + dt [W sigma - sigma W + E / (1 - nu^2) ((1 - nu) D + nu tr(D) I)],
  // D and W the symmetric and skew parts of L.
  Mat<2> elastic_update(const Mat<2>& stress, const Mat<2>& velocity_gradient, double dt) const;

  // Returns `total` (the in-plane stress with the earth pressure) brought
  // back onto Mohr-Coulomb's envelope of cohesion c [Pa] and friction angle
  // phi [rad] in the plane's principal stresses, at its own mean stress:
  // (s1 - s2) / 2 <= c cos(phi) - (s1 + s2) / 2 sin(phi); beyond the apex
  // (all tension above c / tan(phi)) it is the apex, isotropic. With phi = 0
  // the tension is cut off at c. `yielded` says whether it had to.
  static Mat<2> bounded(const Mat<2>& total, double cohesion, double friction_angle, bool& yielded);
};

}  // namespace mpm
