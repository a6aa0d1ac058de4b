#pragma once

// Conversions between hydraulic conductivity K_h [m s^-1] (what soil tests
// report) and intrinsic permeability kappa [m^2] (what drag laws use).
namespace cosim::exchange {

// kappa = K_h mu_f / (rho_f g)   (Tran et al., MPMICE, eq. 31)
double permeability_from_conductivity(double conductivity, double fluid_viscosity,
                                      double fluid_density, double gravity);
// K_h = kappa rho_f g / mu_f     (eq. 31 inverted)
double conductivity_from_permeability(double permeability, double fluid_viscosity,
                                      double fluid_density, double gravity);
// K_h = D_p^2 (1 - phi_s)^3 rho_f g / (180 phi_s^2 mu_f)   (eq. 32, the
// conductivity for which eq. 30 gives the same drag as eq. 29)
double kozeny_carman_conductivity(double grain_size, double solid_fraction, double fluid_viscosity,
                                  double fluid_density, double gravity);

}  // namespace cosim::exchange
