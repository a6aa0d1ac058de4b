#pragma once

#include <algorithm>
#include <cmath>

#include "swe/numerics/face_state.hpp"

namespace swe::solver_2d {

// swe::hllc_flux bit for bit, with every branch turned into a select (both
// sides computed, one kept), so a loop over faces vectorises. The unit tests
// compare it with swe::hllc_flux on wet, dry, sub- and supercritical faces.
inline FaceFlux hllc_flux_selects(const FaceState& l, const FaceState& r, double g) {
  const double sql = std::sqrt(l.h), sqr = std::sqrt(r.h);
  const double sqrt_g = std::sqrt(g);
  const double cl = sqrt_g * sql, cr = sqrt_g * sqr;
  // Einfeldt's speeds, Toro's dry-bed speeds (swe::detail::wave_speeds).
  const double u_roe = (sql * l.un + sqr * r.un) / (sql + sqr);
  const double c_roe = std::sqrt(0.5 * g * (l.h + r.h));
  const bool left_dry = l.h <= 0.0, right_dry = r.h <= 0.0;
  const double sl = left_dry    ? r.un - 2.0 * cr
                    : right_dry ? l.un - cl
                                : std::min(l.un - cl, u_roe - c_roe);
  const double sr = left_dry    ? r.un + cr
                    : right_dry ? l.un + 2.0 * cl
                                : std::max(r.un + cr, u_roe + c_roe);

  const FaceFlux fl = physical_flux(l, g), fr = physical_flux(r, g);
  const double inv = 1.0 / (sr - sl);
  const double mass = (sr * fl.mass - sl * fr.mass + sl * sr * (r.h - l.h)) * inv;
  const double normal_momentum =
      (sr * fl.normal_momentum - sl * fr.normal_momentum + sl * sr * (r.h * r.un - l.h * l.un)) *
      inv;
  const double denominator = r.h * (r.un - sr) - l.h * (l.un - sl);
  const double s_star = denominator != 0.0
                            ? (sl * r.h * (r.un - sr) - sr * l.h * (l.un - sl)) / denominator
                            : 0.5 * (sl + sr);
  const double tangential_momentum = mass * (s_star >= 0.0 ? l.ut : r.ut);

  const bool both_dry = std::max(l.h, r.h) <= 0.0;
  auto pick = [&](double left, double right, double star) {
    return both_dry ? 0.0 : sl >= 0.0 ? left : sr <= 0.0 ? right : star;
  };
  return {pick(fl.mass, fr.mass, mass),
          pick(fl.normal_momentum, fr.normal_momentum, normal_momentum),
          pick(fl.tangential_momentum, fr.tangential_momentum, tangential_momentum)};
}

}  // namespace swe::solver_2d
