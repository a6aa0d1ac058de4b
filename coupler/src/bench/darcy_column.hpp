#pragma once

#include <cmath>

// Tran et al., MPMICE, "Fluid flow through isothermal porous media": water driven by dp through a
// column of length L of grains of size d at solid fraction phi_s moves through the pores at
//   U_f = (1/n) d^2 (1 - phi_s)^3 / (180 phi_s^2 mu) dp / L,  n = 1 - phi_s  (eq. 98).
namespace cosim::bench {

struct DarcyColumn {
  double grain_size = 1.0e-3;  // d [m]
  double viscosity = 1.0e-3;   // mu [Pa s]
  double length = 1.0;         // L [m]

  double pore_velocity(double phi_s, double dp) const {
    const double n = 1.0 - phi_s;
    return (1.0 / n) * grain_size * grain_size * std::pow(1.0 - phi_s, 3) /
           (180.0 * phi_s * phi_s * viscosity) * dp / length;
  }
};

}  // namespace cosim::bench
