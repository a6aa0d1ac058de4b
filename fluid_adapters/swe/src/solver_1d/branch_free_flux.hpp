#pragma once

#include <algorithm>
#include <cmath>

#include "swe/scheme.hpp"

// The 1D face fluxes of swe/numerics/riemann_solvers.hpp without early
// returns: every case is evaluated and the result selected, so a loop over
// faces vectorises. Each case repeats the shared solver's arithmetic
// operation by operation, so the fluxes are bitwise the same (the values a
// case computes where it is not selected may be inf or NaN; they are never
// used). Only mass and normal momentum: the tangential velocity is zero in
// 1D, where HLLC's two fluxes are HLL's.
namespace swe::solver_1d {

struct FaceFlux1d {
  double mass;
  double momentum;
};

// HLL with Einfeldt's speeds and Toro's dry-bed speeds (as swe::hll_flux).
// sqrt_g = sqrt(g); sql, sqr = sqrt(hl), sqrt(hr).
inline FaceFlux1d hll_flux_1d(double hl, double ul, double hr, double ur, double sql, double sqr,
                              double g, double sqrt_g) {
  const double cl = sqrt_g * sql, cr = sqrt_g * sqr;
  const double u_roe = (sql * ul + sqr * ur) / (sql + sqr);
  const double c_roe = std::sqrt(0.5 * g * (hl + hr));
  const bool dry_l = hl <= 0.0, dry_r = hr <= 0.0;
  const double sl = dry_l ? ur - 2.0 * cr : dry_r ? ul - cl : std::min(ul - cl, u_roe - c_roe);
  const double sr = dry_l ? ur + cr : dry_r ? ul + 2.0 * cl : std::max(ur + cr, u_roe + c_roe);

  const double ql = hl * ul, qr = hr * ur;
  const double pl = ql * ul + 0.5 * g * hl * hl, pr = qr * ur + 0.5 * g * hr * hr;
  const double inv = 1.0 / (sr - sl);
  const double mass = (sr * ql - sl * qr + sl * sr * (hr - hl)) * inv;
  const double momentum = (sr * pl - sl * pr + sl * sr * (hr * ur - hl * ul)) * inv;

  // Nested selects of doubles, not && of bools: GCC 12 vectorises only those.
  const double upwind_mass = sl >= 0.0 ? ql : sr <= 0.0 ? qr : mass;
  const double upwind_momentum = sl >= 0.0 ? pl : sr <= 0.0 ? pr : momentum;
  return {dry_l ? (dry_r ? 0.0 : upwind_mass) : upwind_mass,
          dry_l ? (dry_r ? 0.0 : upwind_momentum) : upwind_momentum};
}

// Roe with the Harten-Hyman entropy fix, HLL at a face with a dry side (as
// swe::roe_flux; Zheng et al., eqs. 30-32).
inline FaceFlux1d roe_flux_1d(double hl, double ul, double hr, double ur, double sql, double sqr,
                              double g, double sqrt_g) {
  const double u = (sql * ul + sqr * ur) / (sql + sqr);
  const double c = std::sqrt(0.5 * g * (hl + hr));
  const double lambda1 = u - c, lambda2 = u + c;
  const double dh = hr - hl, dq = hr * ur - hl * ul;
  const double alpha1 = (lambda2 * dh - dq) / (2.0 * c);
  const double alpha2 = (dq - lambda1 * dh) / (2.0 * c);
  auto entropy_fixed = [](double lambda, double lambda_l, double lambda_r) {
    const double delta = std::max(std::max(0.0, lambda - lambda_l), lambda_r - lambda);
    const double a = std::abs(lambda);
    const double fixed = 0.5 * (lambda * lambda / delta + delta);
    return a < delta ? fixed : a;
  };
  const double a1 = entropy_fixed(lambda1, ul - sqrt_g * sql, ur - sqrt_g * sqr);
  const double a2 = entropy_fixed(lambda2, ul + sqrt_g * sql, ur + sqrt_g * sqr);
  const double ql = hl * ul, qr = hr * ur;
  const double pl = ql * ul + 0.5 * g * hl * hl, pr = qr * ur + 0.5 * g * hr * hr;
  const double mass = 0.5 * (ql + qr - a1 * alpha1 - a2 * alpha2);
  const double momentum = 0.5 * (pl + pr - a1 * alpha1 * lambda1 - a2 * alpha2 * lambda2);

  const FaceFlux1d hll = hll_flux_1d(hl, ul, hr, ur, sql, sqr, g, sqrt_g);
  return {hl <= 0.0   ? hll.mass
          : hr <= 0.0 ? hll.mass
                      : mass,
          hl <= 0.0   ? hll.momentum
          : hr <= 0.0 ? hll.momentum
                      : momentum};
}

// Roe's plain formula, without the entropy fix and the dry-side fallback,
// and where it is all of swe::roe_flux: `plain` is 1 where both sides are
// wet and neither wave is a transonic rarefaction (the entropy fix leaves
// |lambda| as it is), else 0 (rare; the caller then calls swe::roe_flux).
// This spares every face the entropy fix's divisions and the HLL flux.
struct PlainRoeFlux1d {
  double mass;
  double momentum;
  double plain;
};

inline PlainRoeFlux1d plain_roe_flux_1d(double hl, double ul, double hr, double ur, double g,
                                        double sqrt_g) {
  const double sql = std::sqrt(hl), sqr = std::sqrt(hr);
  const double u = (sql * ul + sqr * ur) / (sql + sqr);
  const double c = std::sqrt(0.5 * g * (hl + hr));
  const double lambda1 = u - c, lambda2 = u + c;
  const double dh = hr - hl, dq = hr * ur - hl * ul;
  const double alpha1 = (lambda2 * dh - dq) / (2.0 * c);
  const double alpha2 = (dq - lambda1 * dh) / (2.0 * c);
  const double delta1 =
      std::max(std::max(0.0, lambda1 - (ul - sqrt_g * sql)), (ur - sqrt_g * sqr) - lambda1);
  const double delta2 =
      std::max(std::max(0.0, lambda2 - (ul + sqrt_g * sql)), (ur + sqrt_g * sqr) - lambda2);
  const double a1 = std::abs(lambda1), a2 = std::abs(lambda2);
  const double ql = hl * ul, qr = hr * ur;
  const double pl = ql * ul + 0.5 * g * hl * hl, pr = qr * ur + 0.5 * g * hr * hr;
  // Nested selects of doubles, not || of bools: GCC 12 vectorises only those.
  const double plain = hl <= 0.0     ? 0.0
                       : hr <= 0.0   ? 0.0
                       : a1 < delta1 ? 0.0
                       : a2 < delta2 ? 0.0
                                     : 1.0;
  return {0.5 * (ql + qr - a1 * alpha1 - a2 * alpha2),
          0.5 * (pl + pr - a1 * alpha1 * lambda1 - a2 * alpha2 * lambda2), plain};
}

template <FluxKind flux>
inline FaceFlux1d face_flux_1d(double hl, double ul, double hr, double ur, double g,
                               double sqrt_g) {
  const double sql = std::sqrt(hl), sqr = std::sqrt(hr);
  if constexpr (flux == FluxKind::roe) {
    return roe_flux_1d(hl, ul, hr, ur, sql, sqr, g, sqrt_g);
  } else {
    return hll_flux_1d(hl, ul, hr, ur, sql, sqr, g, sqrt_g);
  }
}

}  // namespace swe::solver_1d
