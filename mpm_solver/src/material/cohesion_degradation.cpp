#include "mpm/material/cohesion_degradation.hpp"

namespace mpm {

using cosim::config::Node;
using cosim::config::Schema;

Schema& CohesionDegradation::add_keys(Schema& schema) {
  Schema block = Schema::object();
  block.required("critical_volumetric_strain", Schema::number().positive(),
                 "eps_c: the cohesion is gone once |volumetric strain| accumulated while yielding "
                 "reaches 2 eps_c.");
  return schema.optional(
      "cohesion_degradation", block,
      "Loss of cohesion by fragmentation while yielding (van den Bout et al., OpenLISEM Hazard, "
      "eq. 26); damage = 1 - c/c0 is recorded per point. Absent: the cohesion stays.");
}

CohesionDegradation CohesionDegradation::read(const Node& node) {
  const auto block = node.find("cohesion_degradation");
  if (!block) return {};
  return CohesionDegradation((*block)["critical_volumetric_strain"].as<double>());
}

}  // namespace mpm
