#pragma once

#include <memory>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "mpm/material/elastic_constants.hpp"
#include "mpm/material/material.hpp"

namespace mpm {

// Hooke's law in rate form: sigma_{n+1} = sigma_n + lambda tr(d eps) I + 2 G d eps.
class LinearElastic final : public Material {
 public:
  static constexpr std::string_view name = "linear_elastic";
  static cosim::config::Schema schema();
  static std::unique_ptr<Material> make(const cosim::config::Node& parameters);

  LinearElastic(CommonProperties common, ObjectiveRate rate, ElasticConstants elastic)
      : Material(common, rate), elastic_(elastic) {}

  std::string_view type() const override { return name; }
  double bulk_modulus() const override { return elastic_.bulk; }
  double shear_modulus() const override { return elastic_.shear; }
  void update(const Deformation& deformation, MaterialState& state) const override;

 private:
  ElasticConstants elastic_;
};

}  // namespace mpm
