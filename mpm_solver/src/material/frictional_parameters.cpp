#include "mpm/material/frictional_parameters.hpp"

#include <cmath>

#include "mpm/material/material_parameters.hpp"

namespace mpm {

using cosim::config::Node;
using cosim::config::Schema;

Schema& FrictionalParameters::add_keys(Schema& schema) {
  material_parameters::add_elastic_keys(schema);
  FrictionSoftening::add_keys(schema);
  schema
      .optional("cohesion", Schema::number().non_negative().unit("Pa").default_value("0"),
                "Cohesion c0.")
      .optional("tensile_strength", Schema::number().non_negative().unit("Pa").default_note("none"),
                "Tension cut-off sigma_t (effective stress, tension positive): on the major "
                "principal stress for "
                "mohr_coulomb, on the mean stress for drucker_prager. It only acts below the apex "
                "of the shear "
                "surface, which bounds tension anyway, and degrades with the cohesion. Absent: no "
                "cut-off beyond "
                "the apex.");
  return CohesionDegradation::add_keys(schema);
}

FrictionalParameters FrictionalParameters::read(const Node& node) {
  return {material_parameters::read_elastic_constants(node), FrictionSoftening::read(node),
          node.get<double>("cohesion"),
          node.get("tensile_strength", std::numeric_limits<double>::infinity()),
          CohesionDegradation::read(node)};
}

void FrictionalParameters::record_plastic_step(const Tensor& correction,
                                               double volumetric_strain_increment,
                                               MaterialState& state) const {
  const double mean = correction.trace() / 3.0;
  // d eps^p = C^-1 correction: deviatoric part dev(correction) / 2G, trace mean / K.
  const double deviatoric_norm =
      (correction - mean * Tensor::Identity()).norm() / (2.0 * elastic.shear);
  state.plastic_strain += std::sqrt(2.0 / 3.0) * deviatoric_norm;
  state.internal[0] += mean / elastic.bulk;
  state.damage = degradation.damage_after(state.damage, volumetric_strain_increment);
}

}  // namespace mpm
