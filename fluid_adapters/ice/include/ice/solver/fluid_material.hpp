#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ice/eos/equation_of_state.hpp"

namespace ice {

// One fluid material of the ICE solver (water, air, ...): its equation of
// state and transport coefficients.
struct FluidMaterial {
  std::string name;
  std::shared_ptr<const EquationOfState> eos;
  double viscosity = 0.0;             // dynamic mu [Pa s]
  double thermal_conductivity = 0.0;  // k [W/(m K)]
};

// Pairwise exchange coefficients between the materials, symmetric N x N
// row-major, zero diagonal (Tran et al., MPMICE, eqs. 23 and 48):
// momentum K_ij [kg m^-3 s^-1] and heat H_ij [W m^-3 K^-1]. In a cell the
// pair exchanges with K_ij phi_i phi_j (and H_ij phi_i phi_j), so a material
// that is nearly absent couples in proportion to its volume; K = 1e15 makes
// the pair move as one (a water-air interface).
struct ExchangeCoefficients {
  int materials = 0;
  std::vector<double> momentum;
  std::vector<double> heat;

  static ExchangeCoefficients none(int materials) {
    const auto n = static_cast<std::size_t>(materials) * static_cast<std::size_t>(materials);
    return {materials, std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  }
  void set(int i, int j, double momentum_coefficient, double heat_coefficient) {
    const auto ij = static_cast<std::size_t>(i * materials + j);
    const auto ji = static_cast<std::size_t>(j * materials + i);
    momentum[ij] = momentum[ji] = momentum_coefficient;
    heat[ij] = heat[ji] = heat_coefficient;
  }
};

}  // namespace ice
