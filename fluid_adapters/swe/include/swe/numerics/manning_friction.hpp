#pragma once

#include <cmath>

namespace swe {

// Semi-implicit Manning friction step (Zheng et al., eqs. 35-36):
//   (hu)^{n+1} = (hu)~ / (1 + dt g M_b^2 |u~| / h~^{4/3}),
// applied to every momentum component with the speed |u~| of the velocity
// vector. It only ever shrinks the momentum, so it is stable for any dt and
// any depth. Returns the factor.
inline double manning_factor(double h, double speed, double g, double manning, double dt) {
  if (manning <= 0.0 || h <= 0.0) return 1.0;
  const double h43 = h * std::cbrt(h);
  return 1.0 / (1.0 + dt * g * manning * manning * speed / h43);
}

// The bed shear stress the water exerts on the bed [Pa] along one velocity
// component u_i (Zheng et al., eq. 10, with the sign of the force on the bed):
//   tau_i = rho g M_b^2 u_i |u| / h^{1/3}.
inline double manning_bed_shear(double h, double u_i, double speed, double g, double manning,
                                double density) {
  if (manning <= 0.0 || h <= 0.0) return 0.0;
  return density * g * manning * manning * u_i * speed / std::cbrt(h);
}

}  // namespace swe
