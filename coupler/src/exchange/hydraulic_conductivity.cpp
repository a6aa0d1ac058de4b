#include "exchange/hydraulic_conductivity.hpp"

namespace cosim::exchange {

double permeability_from_conductivity(double conductivity, double fluid_viscosity,
                                      double fluid_density, double gravity) {
  return conductivity * fluid_viscosity / (fluid_density * gravity);  // Tran et al., eq. 31
}

double conductivity_from_permeability(double permeability, double fluid_viscosity,
                                      double fluid_density, double gravity) {
  return permeability * fluid_density * gravity / fluid_viscosity;
}

double kozeny_carman_conductivity(double grain_size, double solid_fraction, double fluid_viscosity,
                                  double fluid_density, double gravity) {
  const double phi_s = solid_fraction;
  const double n = 1.0 - phi_s;
  return grain_size * grain_size * n * n * n * fluid_density * gravity /
         (180.0 * phi_s * phi_s * fluid_viscosity);  // Tran et al., eq. 32
}

}  // namespace cosim::exchange
