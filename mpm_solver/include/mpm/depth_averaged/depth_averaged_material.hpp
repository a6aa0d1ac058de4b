#pragma once

#include <string>

#include "mpm/material/cohesion_degradation.hpp"

namespace mpm {

// A mass moving as a depth-averaged column: its bulk density, the internal
// friction that sets its earth pressure, the Coulomb friction on its bed
// (van den Bout et al., OpenLISEM Hazard, eq. 36: |S| = N tan(delta)), and a
// cohesion that fragmentation degrades (eq. 26).
struct DepthAveragedMaterial {
  std::string name;
  double density = 0.0;                  // rho [kg/m^3]
  double internal_friction_angle = 0.0;  // phi [rad]
  double basal_friction_angle = 0.0;     // delta [rad]
  double cohesion = 0.0;                 // c0 [Pa]
  CohesionDegradation degradation;

  // Throws std::invalid_argument naming the material and the bad value.
  void check() const;
};

}  // namespace mpm
