#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "mpm/material/frictional_parameters.hpp"
#include "mpm/material/material.hpp"

namespace mpm {

// Which Mohr-Coulomb surface the Drucker-Prager cone is fitted to.
enum class DruckerPragerMatch {
  plane_strain,      // Zheng et al., eqs. 3-4; van den Bout et al., eq. 20
  compression_cone,  // through the triaxial compression corners (outer cone)
  extension_cone,    // through the triaxial extension corners (inner cone)
};

// The cone f = alpha_phi I1 + sqrt(J2) - k_c (Zheng et al., eq. 3; tension
// positive I1) with plastic potential g = alpha_psi I1 + sqrt(J2), cut off in
// tension at the mean stress p <= sigma_t.
struct DruckerPragerCone {
  double alpha_friction = 0.0;                                        // alpha_phi
  double alpha_dilation = 0.0;                                        // alpha_psi
  double strength = 0.0;                                              // k_c [Pa]
  double tensile_strength = std::numeric_limits<double>::infinity();  // on p [Pa]

  // alpha and k of a Mohr-Coulomb angle and cohesion, e.g. in plane strain
  // alpha = tan phi / sqrt(9 + 12 tan^2 phi), k = 3 c / sqrt(9 + 12 tan^2 phi)
  // (van den Bout et al., eq. 20); the same rule with psi gives alpha_psi.
  static DruckerPragerCone matched(DruckerPragerMatch match, double friction_angle,
                                   double dilation_angle, double cohesion, double tensile_strength);

  // Mean stress of the apex, k / (3 alpha), infinite for alpha = 0.
  double apex() const;
  // The cut-off in force: min(sigma_t, apex).
  double mean_stress_limit() const;
  // max(f, p - sigma_t) [Pa].
  double yield(const Tensor& stress) const;
};

// Exact return for perfect plasticity within the step (Zheng et al., eq. 4 integrated in closed
// form): cone:    dlambda = f_trial / (9 K alpha_phi alpha_psi + G),
//          I1 = I1_trial - 9 K alpha_psi dlambda, sqrt(J2) = sqrt(J2_trial) - G dlambda, s along
//          s_trial;
// tension: p = sigma_t with s_trial kept, when that is inside the cone;
// corner:  p = min(sigma_t, apex), sqrt(J2) = k - 3 alpha p (the apex when no cut-off is set),
// as Huang et al. and Bui et al. treat stresses beyond the apex.
// Returns the stress after the step.
Tensor drucker_prager_return(const Tensor& trial, const DruckerPragerCone& cone,
                             const ElasticConstants& elastic);

// Non-associated Drucker-Prager elastoplasticity matched to Mohr-Coulomb,
// with the same friction softening, dilatancy, cohesion degradation and
// state variables as MohrCoulomb (see FrictionalParameters).
class DruckerPrager final : public Material {
 public:
  static constexpr std::string_view name = "drucker_prager";
  static cosim::config::Schema schema();
  static std::unique_ptr<Material> make(const cosim::config::Node& parameters);

  DruckerPrager(CommonProperties common, ObjectiveRate rate, FrictionalParameters parameters,
                DruckerPragerMatch match);

  std::string_view type() const override { return name; }
  double bulk_modulus() const override { return parameters_.elastic.bulk; }
  double shear_modulus() const override { return parameters_.elastic.shear; }
  void update(const Deformation& deformation, MaterialState& state) const override;
  double yield_function(const MaterialState& state) const override;
  double friction_angle(const MaterialState& state) const override;

  DruckerPragerCone cone(const MaterialState& state) const;
  const FrictionalParameters& parameters() const { return parameters_; }

 private:
  FrictionalParameters parameters_;
  DruckerPragerMatch match_;
  std::optional<DruckerPragerCone> fixed_cone_;  // without softening or degradation
};

}  // namespace mpm
