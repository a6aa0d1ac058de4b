#pragma once

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"

namespace mpm {

// The mobilised friction and dilation angles of a frictional model as the
// soil softens with accumulated equivalent plastic shear strain eps_p
// (MaterialState::plastic_strain). Tran et al., MPMICE, Figure 20 shows the
// mobilised friction angle falling from its peak to a residual value; here
// the fall is exponential,
//   phi_m(eps_p) = phi_r + (phi_p - phi_r) exp(-eta eps_p),
// continuous and monotone, phi_m(0) = phi_p and phi_m -> phi_r (within
// 1e-3 (phi_p - phi_r) once eta eps_p > 6.9). The dilation angle is either a
// constant psi (capped at phi_m so that the flow never dilates more than an
// associated one) or Rowe's (MPMICE, eq. 100: psi_m = 0 at residual, > 0 before).
class FrictionSoftening {
 public:
  enum class Dilatancy { constant, rowe };

  FrictionSoftening(double peak, double residual, double rate, Dilatancy dilatancy,
                    double dilation_angle);

  // YAML keys friction_angle, residual_friction_angle, softening_rate,
  // dilatancy, dilation_angle (angles in degrees).
  static cosim::config::Schema& add_keys(cosim::config::Schema& schema);
  static FrictionSoftening read(const cosim::config::Node& node);

  double friction_angle(double plastic_strain) const;  // phi_m [rad]
  double dilation_angle(double friction_angle) const;  // psi_m at mobilised phi_m [rad]

  double peak_friction_angle() const { return peak_; }
  double residual_friction_angle() const { return residual_; }
  double softening_rate() const { return rate_; }
  Dilatancy dilatancy() const { return dilatancy_; }

 private:
  double peak_;
  double residual_;
  double rate_;
  Dilatancy dilatancy_;
  double dilation_angle_;
};

}  // namespace mpm
