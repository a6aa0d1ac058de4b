#pragma once

#include <limits>

#include "ice/eos/ideal_gas.hpp"
#include "ice/eos/linear_water.hpp"

namespace ice::testing {

inline constexpr double eps = std::numeric_limits<double>::epsilon();

// Dry air, gamma = 1.4.
inline IdealGas air() {
  return IdealGas(287.05, 287.05 / 0.4);
}

// Water as in Tran et al., MPMICE, Table 1 (bulk modulus 2.15e9 Pa,
// rho_ref 999.8 kg/m3), defaults otherwise.
inline LinearWater water() {
  LinearWaterParameters p;
  p.bulk_modulus = 2.15e9;
  p.reference_density = 999.8;
  return LinearWater(p);
}

}  // namespace ice::testing
