#pragma once

#include <string>

#include "mpm/depth_averaged/in_plane_stress.hpp"
#include "mpm/material/cohesion_degradation.hpp"

namespace mpm {

// A mass moving as a depth-averaged column: its bulk density, the internal
// friction that sets its earth pressure, the Coulomb friction on its bed
// (van den Bout et al., OpenLISEM Hazard, eq. 36: |S| = N tan(delta)), a
// cohesion that fragmentation degrades (eq. 26), and how much of a
// surrounding fluid's pressure reaches its base (eq. 39).
struct DepthAveragedMaterial {
  std::string name;
  double density = 0.0;                  // rho [kg/m^3]
  double internal_friction_angle = 0.0;  // phi [rad]
  double basal_friction_angle = 0.0;     // delta [rad]
  double cohesion = 0.0;                 // c0 [Pa]
  CohesionDegradation degradation;
  // f_sc at the start: the share of the solids bound in structures (blocks);
  // fragmentation turns them into loose grains (eq. 28).
  double structured_share = 1.0;
  // B of eq. 39: the share of the fluid's pressure that reaches the base
  // through the structured solids (0: an unsaturated block bears on its bed
  // with its full weight; 1: a saturated one is buoyed). Loose grains are
  // always buoyed (eqs. 37, 39), so the base is relieved by
  // ((1 - f_sc) + f_sc B) times the fluid's pressure. The paper's settings
  // use 0, its discussion 1 for saturated masses.
  double basal_pressure_factor = 1.0;
  // epsilon_f of eq. 28 [-]: the volumetric strain over which the structures
  // break up; 0 takes the degradation's critical strain.
  double fragmentation_strain = 0.0;
  // The share of a column's volume that is fluid confined in its structures
  // at the start (f_fc alpha_f / alpha_c of eqs. 1-3): as the structures
  // break up (eq. 28) their fluid is released at the same rate (eq. 27) and
  // leaves the column, which keeps its grains and the rest of its fluid.
  double confined_fluid_fraction = 0.0;
  // The in-plane stress of eq. 43's last term (E = 0: none, the earth
  // pressure alone), bounded by Mohr-Coulomb with the cohesion left and phi.
  InPlaneStress in_plane;

  double structured_share_after(double share, double damage, double volumetric_strain) const;

  // Throws std::invalid_argument naming the material and the bad value.
  void check() const;
};

}  // namespace mpm
