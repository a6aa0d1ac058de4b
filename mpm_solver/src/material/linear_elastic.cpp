#include "mpm/material/linear_elastic.hpp"

#include "mpm/material/material_parameters.hpp"

namespace mpm {

cosim::config::Schema LinearElastic::schema() {
  auto schema = material_parameters::base_schema(
      std::string(name), "Isotropic linear elasticity (Hooke), incremental.");
  return material_parameters::add_elastic_keys(schema);
}

std::unique_ptr<Material> LinearElastic::make(const cosim::config::Node& parameters) {
  return std::make_unique<LinearElastic>(material_parameters::read_common_properties(parameters),
                                         material_parameters::read_objective_rate(parameters),
                                         material_parameters::read_elastic_constants(parameters));
}

void LinearElastic::update(const Deformation& deformation, MaterialState& state) const {
  state.stress += elastic_.stress_increment(deformation.strain_increment);
}

}  // namespace mpm
