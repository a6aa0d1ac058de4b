#pragma once

#include <array>
#include <optional>
#include <string>

namespace ice {

// What a side of the domain does (sides indexed 2 d for the lower and
// 2 d + 1 for the upper side along direction d):
//   wall            no flow through it; tangential velocity free (a symmetry
//                   plane); pressure extrapolated hydrostatically.
//   outflow         zero-gradient (Neumann) pressure, density, velocity and
//                   temperature: the face carries the boundary cell's normal
//                   velocity and is not corrected by the pressure step.
//   fixed_pressure  P = pressure on the face (Dirichlet); the face velocity
//                   follows from the half-cell pressure gradient.
//   inflow          the given velocity on the face; what flows in has the
//                   boundary cell's composition and temperature.
// A side with a temperature is held at it for heat conduction; without one
// it is insulated.
enum class SideType { wall, outflow, fixed_pressure, inflow };

struct SideCondition {
  SideType type = SideType::wall;
  double pressure = 0.0;              // fixed_pressure [Pa]
  std::array<double, 3> velocity{};   // inflow [m/s]
  std::optional<double> temperature;  // fixed temperature [K]; none: insulated
};

std::string to_string(SideType type);

}  // namespace ice
