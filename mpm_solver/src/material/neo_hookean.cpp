#include "mpm/material/neo_hookean.hpp"

#include <cmath>
#include <limits>

#include "mpm/material/material_parameters.hpp"

namespace mpm {

cosim::config::Schema NeoHookean::schema() {
  auto schema =
      material_parameters::base_schema(std::string(name),
                                       "Compressible neo-Hookean hyperelasticity (Tran et al., "
                                       "MPMICE, eq. 15); stress from F, no objective rate.",
                                       false);
  return material_parameters::add_elastic_keys(schema);
}

std::unique_ptr<Material> NeoHookean::make(const cosim::config::Node& parameters) {
  return std::make_unique<NeoHookean>(material_parameters::read_common_properties(parameters),
                                      material_parameters::read_elastic_constants(parameters));
}

Tensor NeoHookean::stress(const Tensor& F) const {
  const double J = F.determinant();
  // No exception here: update runs inside parallel loops; the solver refuses non-finite stresses.
  if (!(J > 0.0)) return Tensor::Constant(std::numeric_limits<double>::quiet_NaN());
  const double lambda = elastic_.lame();
  const double mu = elastic_.shear;
  return lambda * std::log(J) / J * Tensor::Identity() +
         mu / J * (F * F.transpose() - Tensor::Identity());
}

void NeoHookean::update(const Deformation& deformation, MaterialState& state) const {
  state.stress = stress(deformation.deformation_gradient);
}

}  // namespace mpm
