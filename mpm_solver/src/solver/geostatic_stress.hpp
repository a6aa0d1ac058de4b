#pragma once

#include <cmath>
#include <cstddef>
#include <map>
#include <vector>

#include "body_state.hpp"
#include "mpm/case/case_description.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::detail {

// Geostatic initial effective stress of the bodies that ask for it: with z
// the last coordinate (gravity along -z), sigma'_v = -gamma (z_s - z) and
// sigma'_h = K0 sigma'_v (tension positive; plane strain sigma'_zz too).
// K0 defaults to Jaky's 1 - sin(phi) for frictional materials and
// nu / (1 - nu) otherwise; gamma to rho |g| (rho = particle mass / volume);
// z_s to the top of the body's particles above the point (their highest
// upper domain edge in the same column of grid cells).
template <int Dim>
void initialise_geostatic_stress(const CaseDescription& description,
                                 const std::vector<BodyState<Dim>>& bodies, const Vec<Dim>& gravity,
                                 Particles<Dim>& particles) {
  const int up = Dim - 1;
  const double g = gravity.norm();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodySpec& spec = description.bodies[b];
    const BodyState<Dim>& body = bodies[b];
    if (!spec.geostatic || body.is_rigid()) continue;
    const GeostaticStress& geo = *spec.geostatic;
    // Top of the body per column of cells (key: cell index across the horizontal directions).
    const auto column_of = [&](std::size_t p) {
      long key = 0;
      for (int d = 0; d < up; ++d) {
        const double cell = std::floor((particles.position[p][d] - description.grid.origin[d]) /
                                       description.grid.spacing[d]);
        key = key * 1000003L + static_cast<long>(cell);
      }
      return key;
    };
    std::map<long, double> top;
    for (std::size_t p = body.first; p < body.first + body.count; ++p) {
      const double z = particles.position[p][up] + particles.half_length[p][up];
      auto [it, inserted] = top.emplace(column_of(p), z);
      if (!inserted) it->second = std::max(it->second, z);
    }
    MaterialState probe;
    body.material->initialise(probe);
    const double phi = body.material->friction_angle(probe);
    const double K = body.material->bulk_modulus();
    const double G = body.material->shear_modulus();
    const double nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
    const double k0 =
        std::isfinite(geo.k0) ? geo.k0 : (phi > 0.0 ? 1.0 - std::sin(phi) : nu / (1.0 - nu));
    for (std::size_t p = body.first; p < body.first + body.count; ++p) {
      const double gamma = std::isfinite(geo.unit_weight)
                               ? geo.unit_weight
                               : particles.mass[p] / particles.volume[p] * g;
      const double surface = geo.surface ? *geo.surface : top[column_of(p)];
      const double vertical = -gamma * std::max(0.0, surface - particles.position[p][up]);
      Voigt s{};
      for (int d = 0; d < 3; ++d) s[static_cast<std::size_t>(d)] = k0 * vertical;
      s[static_cast<std::size_t>(up)] = vertical;
      particles.stress[p] = s;
    }
  }
}

}  // namespace mpm::detail
