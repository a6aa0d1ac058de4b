#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "mpm/material/frictional_parameters.hpp"
#include "mpm/material/material.hpp"
#include "mpm/material/mohr_coulomb_return.hpp"

namespace mpm {

// Non-associated Mohr-Coulomb elastoplasticity (Tran et al., MPMICE, eq. 16)
// with a tension cut-off, friction softening, constant or Rowe dilatancy
// (MPMICE, eq. 100) and optional cohesion degradation (van den Bout et al.,
// eq. 26). A step: elastic trial stress (Hooke), then, unless the invariant
// bound proves it inside, the corner-aware return in principal space
// (mohr_coulomb_return). The angles, cohesion and cut-off of a step are those
// at its start (explicit in the softening variables).
class MohrCoulomb final : public Material {
 public:
  static constexpr std::string_view name = "mohr_coulomb";
  static cosim::config::Schema schema();
  static std::unique_ptr<Material> make(const cosim::config::Node& parameters);

  MohrCoulomb(CommonProperties common, ObjectiveRate rate, FrictionalParameters parameters);

  std::string_view type() const override { return name; }
  double bulk_modulus() const override { return parameters_.elastic.bulk; }
  double shear_modulus() const override { return parameters_.elastic.shear; }
  void update(const Deformation& deformation, MaterialState& state) const override;
  double yield_function(const MaterialState& state) const override;
  double friction_angle(const MaterialState& state) const override;

  // The surface in force at a state.
  MohrCoulombSurface surface(const MaterialState& state) const;
  const FrictionalParameters& parameters() const { return parameters_; }

 private:
  FrictionalParameters parameters_;
  std::optional<MohrCoulombSurface> fixed_surface_;  // without softening or degradation
};

}  // namespace mpm
