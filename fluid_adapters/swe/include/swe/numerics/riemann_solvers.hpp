#pragma once

#include <algorithm>
#include <cmath>

#include "swe/numerics/face_state.hpp"
#include "swe/scheme.hpp"

// Approximate Riemann solvers for the shallow-water equations along a face
// normal. Depths are >= 0; a side with h == 0 is dry. Header-only so the
// solvers' face loops inline them.
namespace swe {

namespace detail {

// Wave-speed bounds of Einfeldt (HLLE) with the dry-bed speeds of Toro
// (Shock-capturing methods for free-surface shallow flows, 2001, Sec. 10.5).
struct WaveSpeeds {
  double left, right;
};

inline WaveSpeeds wave_speeds(const FaceState& l, const FaceState& r, double g) {
  const double sql = std::sqrt(l.h), sqr = std::sqrt(r.h);
  const double sqrt_g = std::sqrt(g);
  const double cl = sqrt_g * sql, cr = sqrt_g * sqr;
  if (l.h <= 0.0) return {r.un - 2.0 * cr, r.un + cr};
  if (r.h <= 0.0) return {l.un - cl, l.un + 2.0 * cl};
  const double u_roe = (sql * l.un + sqr * r.un) / (sql + sqr);
  const double c_roe = std::sqrt(0.5 * g * (l.h + r.h));
  return {std::min(l.un - cl, u_roe - c_roe), std::max(r.un + cr, u_roe + c_roe)};
}

// Tangential momentum carried passively with the mass flux, taken from the
// side the contact wave leaves behind.
inline double upwind_tangential(double mass_flux, double contact_speed, const FaceState& l,
                                const FaceState& r) {
  return mass_flux * (contact_speed >= 0.0 ? l.ut : r.ut);
}

}  // namespace detail

namespace detail {

// The HLL flux of depth and normal momentum for wave speeds sl < 0 < sr;
// the tangential momentum is left to the caller.
inline FaceFlux hll_between(const FaceState& l, const FaceState& r, double g, double sl,
                            double sr) {
  const FaceFlux fl = physical_flux(l, g), fr = physical_flux(r, g);
  const double inv = 1.0 / (sr - sl);
  FaceFlux f;
  f.mass = (sr * fl.mass - sl * fr.mass + sl * sr * (r.h - l.h)) * inv;
  f.normal_momentum =
      (sr * fl.normal_momentum - sl * fr.normal_momentum + sl * sr * (r.h * r.un - l.h * l.un)) *
      inv;
  return f;
}

}  // namespace detail

// HLL (Harten, Lax & van Leer, SIAM Rev. 25, 1983) with Einfeldt's speeds
// (SIAM J. Numer. Anal. 25, 1988); positivity-preserving.
// The tangential momentum is upwinded with the mass flux.
inline FaceFlux hll_flux(const FaceState& l, const FaceState& r, double g) {
  if (l.h <= 0.0 && r.h <= 0.0) return {};
  const auto [sl, sr] = detail::wave_speeds(l, r, g);
  if (sl >= 0.0) return physical_flux(l, g);
  if (sr <= 0.0) return physical_flux(r, g);
  FaceFlux f = detail::hll_between(l, r, g, sl, sr);
  f.tangential_momentum = detail::upwind_tangential(f.mass, f.mass, l, r);
  return f;
}

// HLLC (Toro, 2001, Sec. 10.4): HLL for depth and normal momentum, plus the
// contact wave s* that carries the tangential velocity, so shear layers are
// not smeared by the acoustic speeds.
inline FaceFlux hllc_flux(const FaceState& l, const FaceState& r, double g) {
  if (l.h <= 0.0 && r.h <= 0.0) return {};
  const auto [sl, sr] = detail::wave_speeds(l, r, g);
  if (sl >= 0.0) return physical_flux(l, g);
  if (sr <= 0.0) return physical_flux(r, g);
  FaceFlux f = detail::hll_between(l, r, g, sl, sr);
  const double denominator = r.h * (r.un - sr) - l.h * (l.un - sl);
  const double s_star = denominator != 0.0
                            ? (sl * r.h * (r.un - sr) - sr * l.h * (l.un - sl)) / denominator
                            : 0.5 * (sl + sr);
  f.tangential_momentum = detail::upwind_tangential(f.mass, s_star, l, r);
  return f;
}

// Roe's flux (Roe, J. Comput. Phys. 43, 1981; Zheng et al., eqs. 30-32) with
// Roe-averaged velocity
//   u^ = (sqrt(h_l) u_l + sqrt(h_r) u_r) / (sqrt(h_l) + sqrt(h_r)),  h^ = (h_l + h_r) / 2
// (the denominator printed in eq. 31 is a typo for this one), and the
// Harten-Hyman entropy fix (J. Comput. Phys. 50, 1983) in transonic rarefactions. At a face with a
// dry side it returns the HLL flux: Roe's linearisation is not positivity-preserving there.
inline FaceFlux roe_flux(const FaceState& l, const FaceState& r, double g) {
  if (l.h <= 0.0 || r.h <= 0.0) return hll_flux(l, r, g);
  const double sql = std::sqrt(l.h), sqr = std::sqrt(r.h);
  const double u = (sql * l.un + sqr * r.un) / (sql + sqr);
  const double c = std::sqrt(0.5 * g * (l.h + r.h));
  const double sqrt_g = std::sqrt(g);
  const double lambda1 = u - c, lambda2 = u + c;
  // Wave strengths of the jumps in h and hu on the eigenvectors
  // r1 = (1, lambda1), r2 = (1, lambda2) of A^ (eq. 32).
  const double dh = r.h - l.h, dq = r.h * r.un - l.h * l.un;
  const double alpha1 = (lambda2 * dh - dq) / (2.0 * c);
  const double alpha2 = (dq - lambda1 * dh) / (2.0 * c);
  auto entropy_fixed = [](double lambda, double lambda_l, double lambda_r) {
    const double delta = std::max({0.0, lambda - lambda_l, lambda_r - lambda});
    const double a = std::abs(lambda);
    return a < delta ? 0.5 * (lambda * lambda / delta + delta) : a;
  };
  const double a1 = entropy_fixed(lambda1, l.un - sqrt_g * sql, r.un - sqrt_g * sqr);
  const double a2 = entropy_fixed(lambda2, l.un + sqrt_g * sql, r.un + sqrt_g * sqr);
  const FaceFlux fl = physical_flux(l, g), fr = physical_flux(r, g);
  FaceFlux f;
  f.mass = 0.5 * (fl.mass + fr.mass - a1 * alpha1 - a2 * alpha2);
  f.normal_momentum = 0.5 * (fl.normal_momentum + fr.normal_momentum - a1 * alpha1 * lambda1 -
                             a2 * alpha2 * lambda2);
  f.tangential_momentum = detail::upwind_tangential(f.mass, u, l, r);
  return f;
}

inline FaceFlux numerical_flux(FluxKind kind, const FaceState& l, const FaceState& r, double g) {
  switch (kind) {
    case FluxKind::roe:
      return roe_flux(l, r, g);
    case FluxKind::hll:
      return hll_flux(l, r, g);
    case FluxKind::hllc:
      break;
  }
  return hllc_flux(l, r, g);
}

}  // namespace swe
