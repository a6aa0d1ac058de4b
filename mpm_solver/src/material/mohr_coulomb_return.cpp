#include "mpm/material/mohr_coulomb_return.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>

namespace mpm {

namespace {

constexpr double inv_sqrt3 = 0.57735026918962576451;

// f = a . sigma - a0 with return direction D b.
struct Plane {
  Vec3d a;
  double a0 = 0.0;
  Vec3d return_direction;
};

double value(const Plane& plane, const Vec3d& sigma) {
  return plane.a.dot(sigma) - plane.a0;
}

// Sets of plane indices tried in order; -1 ends a set.
using Set = std::array<int, 3>;
constexpr Set shear_plane{0, -1, -1};
constexpr Set compression_edge{0, 1, -1};
constexpr Set extension_edge{0, 2, -1};
constexpr std::array<Set, 3> tension_planes_and_lines{{
    {3, -1, -1},  // tension plane
    {0, 3, -1},   // shear meets tension
    {3, 4, -1},   // biaxial tension edge
}};
// Points: the cut-off's corners; the
// corner sigma_1 = sigma_2 = sigma_t where four planes meet is tried as each
// of its triples (Caratheodory: a return direction in the cone of four is in
// the cone of some three).
constexpr std::array<Set, 6> tension_corners{{
    {0, 2, 3},  // sigma_1 = sigma_t, sigma_2 = sigma_3 on the shear plane
    {0, 3, 4},  // sigma_1 = sigma_2 = sigma_t on the shear plane
    {1, 3, 4},
    {0, 1, 3},
    {0, 1, 4},
    {3, 4, 5},  // sigma_1 = sigma_2 = sigma_3 = sigma_t
}};

int size_of(const Set& set) {
  return set[2] >= 0 ? 3 : set[1] >= 0 ? 2 : 1;
}

}  // namespace

double MohrCoulombSurface::yield(const Vec3d& principal) const {
  const double shear = (principal[0] - principal[2]) +
                       (principal[0] + principal[2]) * sin_friction - 2.0 * cohesion * cos_friction;
  return std::max(shear, principal[0] - tensile_strength);
}

bool MohrCoulombSurface::surely_inside(const Tensor& stress) const {
  const double p = stress.trace() / 3.0;
  const double q = std::sqrt(0.5 * (stress - p * Tensor::Identity()).squaredNorm());
  const double shear_bound =
      2.0 * q + (2.0 * p + q * inv_sqrt3) * sin_friction - 2.0 * cohesion * cos_friction;
  return shear_bound < 0.0 && p + 2.0 * q * inv_sqrt3 < tensile_strength;
}

PrincipalReturn mohr_coulomb_return(const Vec3d& trial, const MohrCoulombSurface& surface,
                                    const ElasticConstants& elastic) {
  const double sin_phi = surface.sin_friction;
  const double sin_psi = surface.sin_dilation;
  const double strength = 2.0 * surface.cohesion * surface.cos_friction;
  const double lambda = elastic.lame();
  const double two_g = 2.0 * elastic.shear;
  const auto D = [&](const Vec3d& b) -> Vec3d {
    return lambda * b.sum() * Vec3d::Ones() + two_g * b;
  };

  const bool cutoff = surface.has_tension_cutoff();
  const int count = cutoff ? 6 : 3;
  std::array<Plane, 6> planes;
  planes[0] = {
      {1.0 + sin_phi, 0.0, -(1.0 - sin_phi)}, strength, D({1.0 + sin_psi, 0.0, -(1.0 - sin_psi)})};
  planes[1] = {
      {0.0, 1.0 + sin_phi, -(1.0 - sin_phi)}, strength, D({0.0, 1.0 + sin_psi, -(1.0 - sin_psi)})};
  planes[2] = {
      {1.0 + sin_phi, -(1.0 - sin_phi), 0.0}, strength, D({1.0 + sin_psi, -(1.0 - sin_psi), 0.0})};
  for (int i = 0; i < 3; ++i) {
    const Vec3d e = Vec3d::Unit(i);
    planes[static_cast<std::size_t>(3 + i)] = {e, cutoff ? surface.tensile_strength : 0.0, D(e)};
  }

  // The trial is sorted, so planes 0 and 3 are the largest of their kinds.
  if (value(planes[0], trial) <= 0.0 && (!cutoff || value(planes[3], trial) <= 0.0))
    return {trial, 0};

  const double scale = std::max({trial.cwiseAbs().maxCoeff(), strength,
                                 cutoff ? std::abs(surface.tensile_strength) : 0.0, 1e-300});
  const double tolerance = 1e-10 * scale;

  PrincipalReturn best{trial, 0};
  double best_violation = std::numeric_limits<double>::infinity();
  // Returns to the planes of `set`; true when the Kuhn-Tucker conditions hold.
  const auto attempt = [&](const Set& set) {
    const int n = size_of(set);
    for (int k = 0; k < n; ++k) {
      if (set[static_cast<std::size_t>(k)] >= count) return false;
    }
    const auto plane = [&](int k) -> const Plane& {
      return planes[static_cast<std::size_t>(set[static_cast<std::size_t>(k)])];
    };
    Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
    Vec3d rhs = Vec3d::Zero();
    for (int i = 0; i < n; ++i) {
      rhs[i] = value(plane(i), trial);
      for (int j = 0; j < n; ++j) M(i, j) = plane(i).a.dot(plane(j).return_direction);
    }
    Vec3d dlambda = Vec3d::Zero();
    const double size = std::pow(M.diagonal().cwiseAbs().maxCoeff(), n);
    if (n == 1) {
      dlambda[0] = rhs[0] / M(0, 0);
    } else if (n == 2) {
      const double det = M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0);
      if (!(std::abs(det) > 1e-12 * size)) return false;
      dlambda[0] = (M(1, 1) * rhs[0] - M(0, 1) * rhs[1]) / det;
      dlambda[1] = (M(0, 0) * rhs[1] - M(1, 0) * rhs[0]) / det;
    } else {
      const double det = M.determinant();
      if (!(std::abs(det) > 1e-12 * size)) return false;
      dlambda = M.inverse() * rhs;
    }
    Vec3d sigma = trial;
    unsigned active = 0;
    double violation = 0.0;
    for (int k = 0; k < n; ++k) {
      sigma -= dlambda[k] * plane(k).return_direction;
      violation = std::max(violation, -dlambda[k] * plane(k).return_direction.norm());
      active |= 1u << set[static_cast<std::size_t>(k)];
    }
    for (int i = 0; i < count; ++i)
      violation = std::max(violation, value(planes[static_cast<std::size_t>(i)], sigma));
    if (violation < best_violation) {
      best_violation = violation;
      best = {sigma, active};
    }
    return violation <= tolerance;
  };

  if (attempt(shear_plane)) return best;
  // The ordering the plane return broke names the edge to try first.
  const bool compression_first = best.stress[1] - best.stress[0] >= best.stress[2] - best.stress[1];
  if (attempt(compression_first ? compression_edge : extension_edge)) return best;
  if (attempt(compression_first ? extension_edge : compression_edge)) return best;
  if (!cutoff) {
    if (sin_phi > 0.0) return {Vec3d::Constant(surface.apex()), shear_13 | shear_23 | shear_12};
    return best;
  }
  for (const Set& set : tension_planes_and_lines) {
    if (attempt(set)) return best;
  }
  for (const Set& set : tension_corners) {
    if (attempt(set)) return best;
  }
  return best;
}

}  // namespace mpm
