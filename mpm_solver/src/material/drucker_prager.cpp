#include "mpm/material/drucker_prager.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mpm/material/material_parameters.hpp"

namespace mpm {

namespace {

constexpr double sqrt3 = 1.7320508075688772935;

// alpha and k per unit cohesion of a Mohr-Coulomb angle.
std::pair<double, double> match_coefficients(DruckerPragerMatch match, double angle) {
  switch (match) {
    case DruckerPragerMatch::plane_strain: {
      const double t = std::tan(angle);
      const double root = std::sqrt(9.0 + 12.0 * t * t);
      return {t / root, 3.0 / root};
    }
    case DruckerPragerMatch::compression_cone:
    case DruckerPragerMatch::extension_cone: {
      const double s = std::sin(angle);
      const double denominator =
          sqrt3 * (match == DruckerPragerMatch::compression_cone ? 3.0 - s : 3.0 + s);
      return {2.0 * s / denominator, 6.0 * std::cos(angle) / denominator};
    }
  }
  return {0.0, 0.0};
}

}  // namespace

DruckerPragerCone DruckerPragerCone::matched(DruckerPragerMatch match, double friction_angle,
                                             double dilation_angle, double cohesion,
                                             double tensile_strength) {
  const auto [alpha, k_per_c] = match_coefficients(match, friction_angle);
  return {alpha, match_coefficients(match, dilation_angle).first, k_per_c * cohesion,
          tensile_strength};
}

double DruckerPragerCone::apex() const {
  return alpha_friction > 0.0 ? strength / (3.0 * alpha_friction)
                              : std::numeric_limits<double>::infinity();
}

double DruckerPragerCone::mean_stress_limit() const {
  return std::min(tensile_strength, apex());
}

double DruckerPragerCone::yield(const Tensor& stress) const {
  const double p = stress.trace() / 3.0;
  const double q = std::sqrt(0.5 * (stress - p * Tensor::Identity()).squaredNorm());
  return std::max(3.0 * alpha_friction * p + q - strength, p - tensile_strength);
}

Tensor drucker_prager_return(const Tensor& trial, const DruckerPragerCone& cone,
                             const ElasticConstants& elastic) {
  const double p = trial.trace() / 3.0;
  const Tensor s = trial - p * Tensor::Identity();
  const double q = std::sqrt(0.5 * s.squaredNorm());
  const double f = 3.0 * cone.alpha_friction * p + q - cone.strength;
  const double limit = cone.mean_stress_limit();
  if (f <= 0.0 && p <= limit) return trial;
  const double K = elastic.bulk;
  const double G = elastic.shear;
  if (f > 0.0) {
    const double dlambda = f / (9.0 * K * cone.alpha_friction * cone.alpha_dilation + G);
    const double q_new = q - G * dlambda;
    const double p_new = p - 3.0 * K * cone.alpha_dilation * dlambda;
    if (q_new >= 0.0 && p_new <= limit) return p_new * Tensor::Identity() + (q_new / q) * s;
  }
  if (p > limit && 3.0 * cone.alpha_friction * limit + q - cone.strength <= 0.0) {
    return limit * Tensor::Identity() + s;
  }
  const double q_corner = std::max(0.0, cone.strength - 3.0 * cone.alpha_friction * limit);
  return limit * Tensor::Identity() + (q > 0.0 ? q_corner / q : 0.0) * s;
}

cosim::config::Schema DruckerPrager::schema() {
  auto schema = material_parameters::base_schema(
      std::string(name),
      "Non-associated Drucker-Prager elastoplasticity (Zheng et al., eqs. 3-4) matched to "
      "Mohr-Coulomb "
      "(van den Bout et al., eq. 20), with tension cut-off on the mean stress, friction softening, "
      "constant or Rowe "
      "dilatancy and optional cohesion degradation; exact return to cone, cut-off and apex.");
  FrictionalParameters::add_keys(schema);
  return schema.optional(
      "match",
      cosim::config::Schema::one_of({"plane_strain", "compression_cone", "extension_cone"})
          .default_value("plane_strain"),
      "Which Mohr-Coulomb surface the cone fits: plane_strain, alpha = tan phi / sqrt(9 + 12 tan^2 "
      "phi), "
      "k = 3c / sqrt(9 + 12 tan^2 phi); compression_cone (outer), alpha = 2 sin phi / (sqrt3 (3 - "
      "sin phi)), "
      "k = 6 c cos phi / (sqrt3 (3 - sin phi)); extension_cone (inner), the same with 3 + sin phi. "
      "The "
      "dilation coefficient alpha_psi follows the same rule with psi. The tension cut-off applies "
      "to the mean stress.");
}

std::unique_ptr<Material> DruckerPrager::make(const cosim::config::Node& parameters) {
  const std::string match = parameters.get<std::string>("match");
  return std::make_unique<DruckerPrager>(
      material_parameters::read_common_properties(parameters),
      material_parameters::read_objective_rate(parameters), FrictionalParameters::read(parameters),
      match == "compression_cone" ? DruckerPragerMatch::compression_cone
      : match == "extension_cone" ? DruckerPragerMatch::extension_cone
                                  : DruckerPragerMatch::plane_strain);
}

DruckerPrager::DruckerPrager(CommonProperties common, ObjectiveRate rate,
                             FrictionalParameters parameters, DruckerPragerMatch match)
    : Material(common, rate), parameters_(std::move(parameters)), match_(match) {
  if (parameters_.friction.softening_rate() == 0.0 && !parameters_.degradation.enabled())
    fixed_cone_ = cone(MaterialState{});
}

DruckerPragerCone DruckerPrager::cone(const MaterialState& state) const {
  if (fixed_cone_) return *fixed_cone_;
  const double phi = parameters_.friction.friction_angle(state.plastic_strain);
  return DruckerPragerCone::matched(match_, phi, parameters_.friction.dilation_angle(phi),
                                    parameters_.cohesion_at(state),
                                    parameters_.tensile_strength_at(state));
}

void DruckerPrager::update(const Deformation& deformation, MaterialState& state) const {
  const Tensor trial =
      state.stress + parameters_.elastic.stress_increment(deformation.strain_increment);
  state.stress = drucker_prager_return(trial, cone(state), parameters_.elastic);
  if (state.stress == trial) return;
  parameters_.record_plastic_step(trial - state.stress, deformation.strain_increment.trace(),
                                  state);
}

double DruckerPrager::yield_function(const MaterialState& state) const {
  return cone(state).yield(state.stress);
}

double DruckerPrager::friction_angle(const MaterialState& state) const {
  return parameters_.friction.friction_angle(state.plastic_strain);
}

}  // namespace mpm
