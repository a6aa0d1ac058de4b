#pragma once

#include <memory>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "mpm/material/elastic_constants.hpp"
#include "mpm/material/material.hpp"

namespace mpm {

// Compressible neo-Hookean hyperelasticity, Tran et al., MPMICE, eq. 15:
//   sigma = lambda ln(J) / J I + mu / J (F F^T - I),
// with the Lame constants lambda and mu of the configured E and nu. The stress
// depends on F alone, so it is objective without any rate.
class NeoHookean final : public Material {
 public:
  static constexpr std::string_view name = "neo_hookean";
  static cosim::config::Schema schema();
  static std::unique_ptr<Material> make(const cosim::config::Node& parameters);

  NeoHookean(CommonProperties common, ElasticConstants elastic)
      : Material(common, ObjectiveRate::jaumann), elastic_(elastic) {}

  std::string_view type() const override { return name; }
  // The moduli at F = I.
  double bulk_modulus() const override { return elastic_.bulk; }
  double shear_modulus() const override { return elastic_.shear; }
  bool is_hyperelastic() const override { return true; }
  void update(const Deformation& deformation, MaterialState& state) const override;

  Tensor stress(const Tensor& deformation_gradient) const;

 private:
  ElasticConstants elastic_;
};

}  // namespace mpm
