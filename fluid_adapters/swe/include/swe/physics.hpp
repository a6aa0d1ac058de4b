#pragma once

namespace swe {

// Physical constants of one shallow-water run (SI).
struct Physics {
  double gravity = 9.81;    // [m/s^2], acts along -z
  double density = 1000.0;  // water [kg/m^3]; only the bed traction uses it
  double manning = 0.0;     // Manning coefficient M_b [s/m^(1/3)] (Zheng et al., eq. 8)
  // Depth below which a cell counts as dry: its velocity is zero and it
  // carries no momentum. Its water stays (mass is never clipped).
  double dry_depth = 1.0e-6;  // [m]
};

}  // namespace swe
