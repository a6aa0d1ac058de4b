#include "mpm/material/friction_softening.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mpm/material/material_parameters.hpp"
#include "mpm/material/rowe_dilatancy.hpp"

namespace mpm {

using cosim::config::Node;
using cosim::config::Schema;

FrictionSoftening::FrictionSoftening(double peak, double residual, double rate, Dilatancy dilatancy,
                                     double dilation_angle)
    : peak_(peak),
      residual_(residual),
      rate_(rate),
      dilatancy_(dilatancy),
      dilation_angle_(dilation_angle) {}

Schema& FrictionSoftening::add_keys(Schema& schema) {
  return schema
      .required("friction_angle", Schema::number().range(0.0, 90.0).unit("deg"),
                "Peak friction angle phi_p, < 90.")
      .optional("residual_friction_angle",
                Schema::number().range(0.0, 90.0).unit("deg").default_note("friction_angle"),
                "Residual friction angle phi_r <= phi_p; the mobilised angle softens as "
                "phi_r + (phi_p - phi_r) exp(-softening_rate eps_p) with eps_p the accumulated "
                "equivalent "
                "plastic shear strain (Tran et al., MPMICE, Figure 20). Below friction_angle it "
                "needs softening_rate > 0.")
      .optional("softening_rate", Schema::number().non_negative().default_value("0"),
                "eta of the exponential softening law [-]; 0: no softening.")
      .optional("dilatancy", Schema::one_of({"constant", "rowe"}).default_value("constant"),
                "constant: the dilation angle is dilation_angle (capped at the mobilised friction "
                "angle); "
                "rowe: Rowe's stress dilatancy, sin psi = (sin phi_m - sin phi_r) / (1 - sin phi_r "
                "sin phi_m) "
                "clamped at psi >= 0 (Tran et al., MPMICE, eq. 100).")
      .optional("dilation_angle", Schema::number().range(0.0, 90.0).unit("deg").default_note("0"),
                "Dilation angle psi <= friction_angle, with dilatancy: constant only.");
}

FrictionSoftening FrictionSoftening::read(const Node& node) {
  using material_parameters::read_angle;
  const double peak = read_angle(node, "friction_angle", 0.0);
  const double residual =
      read_angle(node, "residual_friction_angle", peak * 180.0 / std::numbers::pi);
  const double rate = node.get<double>("softening_rate");
  if (residual > peak) {
    node["residual_friction_angle"].fail(
        fmt::format("residual_friction_angle must be <= friction_angle ({} deg)",
                    node["friction_angle"].as<double>()));
  }
  if (residual < peak && !(rate > 0.0)) {
    node["residual_friction_angle"].fail(
        "residual_friction_angle below friction_angle needs softening_rate > 0 to be reached");
  }
  const bool rowe = node.get<std::string>("dilatancy") == "rowe";
  if (rowe && node.has("dilation_angle")) {
    node["dilation_angle"].fail_at_key("dilation_angle is not used with dilatancy: rowe");
  }
  const double dilation = read_angle(node, "dilation_angle", 0.0);
  if (dilation > peak) {
    node["dilation_angle"].fail(fmt::format("dilation_angle must be <= friction_angle ({} deg)",
                                            node["friction_angle"].as<double>()));
  }
  return {peak, residual, rate, rowe ? Dilatancy::rowe : Dilatancy::constant, dilation};
}

double FrictionSoftening::friction_angle(double plastic_strain) const {
  if (rate_ == 0.0) return peak_;
  return residual_ + (peak_ - residual_) * std::exp(-rate_ * plastic_strain);
}

double FrictionSoftening::dilation_angle(double mobilised_friction_angle) const {
  if (dilatancy_ == Dilatancy::rowe)
    return rowe_dilation_angle(mobilised_friction_angle, residual_);
  return std::min(dilation_angle_, mobilised_friction_angle);
}

}  // namespace mpm
