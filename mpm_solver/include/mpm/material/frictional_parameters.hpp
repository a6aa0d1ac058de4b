#pragma once

#include <limits>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "mpm/material/cohesion_degradation.hpp"
#include "mpm/material/elastic_constants.hpp"
#include "mpm/material/friction_softening.hpp"
#include "mpm/material/material.hpp"

namespace mpm {

// What the Mohr-Coulomb and Drucker-Prager models share: elasticity, the
// softening friction law, cohesion with its optional degradation, a tension
// cut-off, and the bookkeeping of a plastic step.
//
// MaterialState use: plastic_strain = accumulated equivalent plastic shear
// strain eps_p = sum sqrt(2/3 de^p : de^p) (de^p the deviatoric plastic
// strain increment); damage = 1 - c/c0; internal[0] = accumulated plastic
// volumetric strain sum tr(d eps^p) (positive when dilating); internal[1] unused.
struct FrictionalParameters {
  ElasticConstants elastic;
  FrictionSoftening friction;
  double cohesion = 0.0;  // c0 [Pa]
  double tensile_strength =
      std::numeric_limits<double>::infinity();  // sigma_t [Pa]; infinite: none
  CohesionDegradation degradation;

  // The elastic keys, the friction keys, cohesion, tensile_strength and cohesion_degradation.
  static cosim::config::Schema& add_keys(cosim::config::Schema& schema);
  static FrictionalParameters read(const cosim::config::Node& node);

  double cohesion_at(const MaterialState& state) const { return cohesion * (1.0 - state.damage); }
  double tensile_strength_at(const MaterialState& state) const {
    return tensile_strength < std::numeric_limits<double>::infinity()
               ? tensile_strength * (1.0 - state.damage)
               : tensile_strength;
  }

  // Records a plastic step whose return took `correction` = sigma_trial - sigma
  // off the trial stress (so d eps^p = C^-1 correction), with total strain increment trace
  // `volumetric_strain_increment`.
  void record_plastic_step(const Tensor& correction, double volumetric_strain_increment,
                           MaterialState& state) const;
};

}  // namespace mpm
