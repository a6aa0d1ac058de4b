#pragma once

#include <cmath>
#include <optional>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"

namespace mpm {

// Loss of cohesion by fragmentation, van den Bout et al., OpenLISEM Hazard,
// eq. 26: while the point yields and c > 0,
//   dc/dt = -c0 / 2 * (d eps_v/dt) / eps_c,
// i.e. bonds of strengths spread uniformly over [0, 2 c0] break as the
// volumetric strain grows to 2 eps_c. Either sign of the volumetric strain
// increment breaks bonds (dilation opens them, compaction crushes them), so
// the damage D = 1 - c/c0 only grows: per plastic step
//   dD = |tr(d eps)| / (2 eps_c),  D <= 1.
// The tension cut-off degrades with the cohesion: sigma_t (1 - D).
class CohesionDegradation {
 public:
  CohesionDegradation() = default;  // disabled
  explicit CohesionDegradation(double critical_volumetric_strain)
      : critical_volumetric_strain_(critical_volumetric_strain) {}

  // The optional `cohesion_degradation: {critical_volumetric_strain: ...}` block.
  static cosim::config::Schema& add_keys(cosim::config::Schema& schema);
  static CohesionDegradation read(const cosim::config::Node& node);

  bool enabled() const { return critical_volumetric_strain_ > 0.0; }
  double critical_volumetric_strain() const { return critical_volumetric_strain_; }

  // Damage after a plastic step with volumetric strain increment tr(d eps).
  double damage_after(double damage, double volumetric_strain_increment) const {
    if (!enabled()) return damage;
    return std::min(
        1.0, damage + 0.5 * std::abs(volumetric_strain_increment) / critical_volumetric_strain_);
  }

 private:
  double critical_volumetric_strain_ = 0.0;
};

}  // namespace mpm
