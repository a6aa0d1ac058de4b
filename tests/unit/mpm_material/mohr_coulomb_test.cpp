#include "mpm/material/mohr_coulomb.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "material_test_support.hpp"
#include "mpm/material/mohr_coulomb_return.hpp"

namespace mpm::testing {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

ElasticConstants soil_elasticity() {
  return ElasticConstants::from_youngs_poisson(2.0e7, 0.3);
}

// Gradients of the potentials of the six planes in sorted principal space.
std::array<Vec3d, 6> potential_gradients(double dilation_angle) {
  const double s = std::sin(dilation_angle);
  return {Vec3d(1 + s, 0, -(1 - s)),
          Vec3d(0, 1 + s, -(1 - s)),
          Vec3d(1 + s, -(1 - s), 0),
          Vec3d::Unit(0),
          Vec3d::Unit(1),
          Vec3d::Unit(2)};
}

std::array<double, 6> plane_values(const MohrCoulombSurface& m, const Vec3d& s) {
  const double sp = m.sin_friction, k = 2 * m.cohesion * m.cos_friction;
  const double t = m.tensile_strength;
  return {(1 + sp) * s[0] - (1 - sp) * s[2] - k,
          (1 + sp) * s[1] - (1 - sp) * s[2] - k,
          (1 + sp) * s[0] - (1 - sp) * s[1] - k,
          s[0] - t,
          s[1] - t,
          s[2] - t};
}

Vec3d plastic_strain(const ElasticConstants& e, const Vec3d& correction) {
  const double mean = correction.mean();
  return (correction - Vec3d::Constant(mean)) / (2 * e.shear) +
         Vec3d::Constant(mean / (3 * e.bulk));
}

std::string region_name(unsigned active) {
  static const std::map<unsigned, std::string> names{
      {0, "elastic"},
      {shear_13, "shear plane"},
      {tension_1, "tension plane"},
      {shear_13 | shear_23, "compression edge"},
      {shear_13 | shear_12, "extension edge"},
      {shear_13 | tension_1, "shear-tension line"},
      {tension_1 | tension_2, "biaxial tension line"},
      {shear_13 | shear_23 | shear_12, "shear apex"},
      {shear_13 | shear_12 | tension_1, "tension corner (2=3)"},
      {tension_1 | tension_2 | tension_3, "tension apex"}};
  const auto it = names.find(active);
  if (it != names.end()) return it->second;
  if ((active & (tension_1 | tension_2)) && (active & (shear_13 | shear_23)))
    return "tension corner (1=2)";
  return "mask " + std::to_string(active);
}

// Random sorted trials returned to surfaces with and without cut-off, for
// non-associated, zero-dilation and associated flow: the stress ends on or
// inside every plane, on the planes it returned to, and the plastic strain
// lies in the cone of those planes' potential gradients (the Kuhn-Tucker conditions).
TEST(MohrCoulombReturn, RandomTrialsEndOnTheSurfaceWithFlowAlongThePotential) {
  const ElasticConstants e = soil_elasticity();
  std::mt19937 rng(11);
  std::map<std::string, int> hits;
  struct Case {
    double phi, psi, c, t;
  };
  const double none = std::numeric_limits<double>::infinity();
  for (const Case& k : {Case{30 * deg, 10 * deg, 1.0e4, none}, Case{35 * deg, 0.0, 2.0e4, 5.0e3},
                        Case{25 * deg, 25 * deg, 1.0e4, none}, Case{40 * deg, 5 * deg, 0.0, none},
                        Case{0.0, 0.0, 1.0e4, 2.0e3}, Case{30 * deg, 20 * deg, 1.0e4, 0.0}}) {
    const auto m = MohrCoulombSurface::from_angles(k.phi, k.psi, k.c, k.t);
    const auto b = potential_gradients(k.psi);
    std::uniform_real_distribution<double> u(-2.0e5, 6.0e4);
    double worst_yield = 0.0, worst_flow = 0.0;
    for (int n = 0; n < 4000; ++n) {
      Vec3d trial(u(rng), u(rng), u(rng));
      std::sort(trial.data(), trial.data() + 3, std::greater<>());
      const PrincipalReturn r = mohr_coulomb_return(trial, m, e);
      const double scale = std::max(trial.cwiseAbs().maxCoeff(), 1e4);
      const auto f = plane_values(m, r.stress);
      const int planes = m.has_tension_cutoff() ? 6 : 3;
      for (int i = 0; i < planes; ++i) {
        worst_yield = std::max(worst_yield, f[static_cast<std::size_t>(i)] / scale);
        if (r.active & (1u << i)) {
          EXPECT_NEAR(f[static_cast<std::size_t>(i)] / scale, 0.0, 1e-8);
        }
      }
      EXPECT_LE(m.yield(r.stress), 1e-8 * scale);
      EXPECT_GE(r.stress[0], r.stress[1] - 1e-8 * scale);
      EXPECT_GE(r.stress[1], r.stress[2] - 1e-8 * scale);
      ++hits[region_name(r.active)];
      if (r.active == 0) {
        EXPECT_EQ(r.stress, trial);
        continue;
      }
      const Vec3d strain = plastic_strain(e, trial - r.stress);
      if (r.active == (shear_13 | shear_23 | shear_12)) {
        // The apex takes what no plane or edge can; with psi < phi its
        // return is not a combination of the potentials' gradients (with
        // psi = 0 they have no volumetric part), only a dilation.
        EXPECT_LT((r.stress - Vec3d::Constant(m.apex())).norm(), 1e-12 * scale);
        EXPECT_GT(strain.sum(), 0.0);
        continue;
      }
      // d eps^p = sum mu_i b_i with mu_i >= 0 over the active planes.
      Eigen::Matrix<double, 3, Eigen::Dynamic> B(3, 0);
      for (int i = 0; i < 6; ++i) {
        if (!(r.active & (1u << i))) continue;
        B.conservativeResize(3, B.cols() + 1);
        B.col(B.cols() - 1) = b[static_cast<std::size_t>(i)];
      }
      const Eigen::VectorXd mu = B.colPivHouseholderQr().solve(strain);
      const double residual = (B * mu - strain).norm() / strain.norm();
      worst_flow = std::max(worst_flow, residual);
      EXPECT_LT(residual, 1e-8) << region_name(r.active);
      EXPECT_GE(mu.minCoeff(), -1e-8 * strain.norm()) << region_name(r.active);
    }
    std::cout << "    phi " << k.phi / deg << " psi " << k.psi / deg << " c " << k.c << " t " << k.t
              << ": worst f/|sigma| " << worst_yield << " (tolerance 1e-8), worst flow residual "
              << worst_flow << " (tolerance 1e-8)\n";
  }
  for (const auto& [name, count] : hits) std::cout << "    " << name << ": " << count << '\n';
  for (const char* region :
       {"elastic", "shear plane", "tension plane", "compression edge", "extension edge",
        "shear-tension line", "biaxial tension line", "shear apex", "tension apex",
        "tension corner (1=2)", "tension corner (2=3)"}) {
    EXPECT_GT(hits[region], 5) << region << " was hardly reached";
  }
}

TEST(MohrCoulombReturn, InvariantBoundNeverCallsAnOutsideStressInside) {
  std::mt19937 rng(13);
  const auto m = MohrCoulombSurface::from_angles(30 * deg, 0.0, 1.0e4, 3.0e3);
  int inside = 0;
  for (int n = 0; n < 20000; ++n) {
    const Tensor stress = random_symmetric(rng, 5e4) - 3e4 * Tensor::Identity();
    if (!m.surely_inside(stress)) continue;
    ++inside;
    Eigen::SelfAdjointEigenSolver<Tensor> eigen(stress);
    EXPECT_LT(m.yield(eigen.eigenvalues().reverse()), 0.0);
  }
  std::cout << "    " << inside << " of 20000 stresses proved inside without eigenvalues\n";
  EXPECT_GT(inside, 1000);
}

const char* const sand =
    "type: mohr_coulomb\ndensity: 2650\nyoungs_modulus: 2.0e7\npoisson_ratio: 0.3\n"
    "friction_angle: 30\ndilation_angle: 10\ncohesion: 1.0e4\ntensile_strength: 5.0e3\n";

TEST(MohrCoulomb, ElasticInsideTheSurface) {
  const auto m = material_from_yaml(sand);
  const auto e = soil_elasticity();
  MaterialState state;
  state.stress = -1e5 * Tensor::Identity();
  Deformation d;
  d.strain_increment(0, 0) = -1e-5;
  d.strain_increment(0, 1) = d.strain_increment(1, 0) = 2e-5;
  m->update(d, state);
  EXPECT_LT(relative_difference(state.stress,
                                -1e5 * Tensor::Identity() + e.stress_increment(d.strain_increment)),
            1e-14);
  EXPECT_EQ(state.plastic_strain, 0.0);
  EXPECT_NEAR(m->bulk_modulus(), e.bulk, 1e-6);
  EXPECT_NEAR(m->shear_modulus(), e.shear, 1e-6);
  EXPECT_NEAR(m->friction_angle(state), 30 * deg, 1e-15);
}

// Random stresses and strain increments through the Material interface: the
// stress ends inside, the plastic strain is coaxial with it, and rotating the
// inputs rotates the result (objectivity of the isotropic return).
TEST(MohrCoulomb, RandomStepsStayAdmissibleCoaxialAndFrameIndifferent) {
  const auto m = material_from_yaml(sand);
  const auto e = soil_elasticity();
  std::mt19937 rng(17);
  int plastic = 0;
  double worst_objectivity = 0.0;
  for (int n = 0; n < 2000; ++n) {
    MaterialState state;
    state.stress = random_symmetric(rng, 2e4) - 4e4 * Tensor::Identity();
    if (m->yield_function(state) > 0.0) continue;
    MaterialState rotated = state;
    Deformation d;
    d.strain_increment = random_symmetric(rng, 4e-3);
    const Tensor Q = random_rotation(rng);
    rotated.stress = Q * state.stress * Q.transpose();
    Deformation dq = d;
    dq.strain_increment = Q * d.strain_increment * Q.transpose();
    const Tensor trial = state.stress + e.stress_increment(d.strain_increment);
    m->update(d, state);
    m->update(dq, rotated);
    const double scale = std::max(1e4, trial.norm());
    EXPECT_LE(m->yield_function(state), 1e-8 * scale);
    const double difference = (Q * state.stress * Q.transpose() - rotated.stress).norm() / scale;
    worst_objectivity = std::max(worst_objectivity, difference);
    EXPECT_LT(difference, 1e-9);
    EXPECT_NEAR(state.plastic_strain, rotated.plastic_strain,
                1e-9 * std::max(1e-3, state.plastic_strain));
    if (state.plastic_strain > 0.0) {
      ++plastic;
      const Tensor strain = e.strain_increment(trial - state.stress);
      EXPECT_LT((strain * state.stress - state.stress * strain).norm(),
                1e-8 * strain.norm() * scale);
    }
  }
  std::cout << "    " << plastic << " plastic steps; worst |Q s Q^T - s(Q)|/|s| "
            << worst_objectivity << " (tolerance 1e-9)\n";
  EXPECT_GT(plastic, 200);
}

// Plane strain, zero cohesion: compressing sigma_yy at fixed width sends the
// point to the shear plane with sigma_zz kept as the intermediate stress.
TEST(MohrCoulomb, PlaneStrainCompressionReachesTheFrictionalLimit) {
  const auto m = material_from_yaml(
      "type: mohr_coulomb\ndensity: 2650\nyoungs_modulus: 2.0e7\npoisson_ratio: "
      "0.3\nfriction_angle: 30\n");
  MaterialState state;
  state.stress = -1e5 * Tensor::Identity();
  Deformation d;
  d.strain_increment(1, 1) = -1e-4;
  d.strain_increment(0, 0) = 0.5e-4;
  for (int n = 0; n < 200; ++n) m->update(d, state);
  const double s1 = state.stress(0, 0), s3 = state.stress(1, 1);
  const double ratio = s3 / s1;  // (1 + sin phi) / (1 - sin phi) = 3 at phi = 30
  std::cout << "    sigma_3 / sigma_1 = " << ratio << " (MC: 3, tolerance 1e-9)\n";
  EXPECT_NEAR(ratio, 3.0, 1e-9);
  EXPECT_LT(state.stress(2, 2), s1);
  EXPECT_GT(state.stress(2, 2), s3);
  EXPECT_GT(state.plastic_strain, 0.0);
  EXPECT_NEAR(state.internal[0], 0.0, 1e-12);  // psi = 0: no plastic volume change
}

TEST(MohrCoulomb, TensionCutOffBoundsThePrincipalStress) {
  const auto m = material_from_yaml(sand);
  std::mt19937 rng(19);
  for (int n = 0; n < 500; ++n) {
    MaterialState state;
    Deformation d;
    d.strain_increment = random_symmetric(rng, 1e-3) + 1e-3 * Tensor::Identity();
    m->update(d, state);
    Eigen::SelfAdjointEigenSolver<Tensor> eigen(state.stress);
    EXPECT_LE(eigen.eigenvalues().maxCoeff(), 5.0e3 * (1.0 + 1e-9));
  }
}

TEST(MohrCoulomb, SofteningLowersTheMobilisedFrictionAngleToResidual) {
  const auto m = material_from_yaml(
      "type: mohr_coulomb\ndensity: 2650\nyoungs_modulus: 1.0e4\npoisson_ratio: 0.3\n"
      "friction_angle: 45\nresidual_friction_angle: 10\nsoftening_rate: 20\ndilatancy: rowe\n");
  MaterialState state;
  state.stress = -1e3 * Tensor::Identity();
  Deformation d;
  d.strain_increment(0, 1) = d.strain_increment(1, 0) = 1e-3;
  double previous = m->friction_angle(state);
  EXPECT_NEAR(previous, 45 * deg, 1e-15);
  for (int n = 0; n < 2000; ++n) {
    m->update(d, state);
    const double phi = m->friction_angle(state);
    EXPECT_LE(phi, previous + 1e-15);
    previous = phi;
  }
  std::cout << "    after shear: eps_p " << state.plastic_strain << ", phi_m " << previous / deg
            << " deg\n";
  EXPECT_GT(state.plastic_strain, 1.0);
  EXPECT_NEAR(previous, 10 * deg, 1e-6);
  EXPECT_GT(state.internal[0], 0.0);  // Rowe dilatancy dilates while phi_m > phi_r
}

TEST(MohrCoulomb, CohesionDegradesWhileYieldingOnly) {
  const auto m = material_from_yaml(
      "type: mohr_coulomb\ndensity: 2650\nyoungs_modulus: 2.0e7\npoisson_ratio: "
      "0.3\nfriction_angle: 30\n"
      "dilation_angle: 20\ncohesion: 1.0e4\ncohesion_degradation: {critical_volumetric_strain: "
      "0.01}\n");
  MaterialState state;
  Deformation d;
  d.strain_increment(0, 0) = -1e-6;
  m->update(d, state);
  EXPECT_EQ(state.damage, 0.0);  // elastic
  d.strain_increment(0, 1) = d.strain_increment(1, 0) = 1e-3;
  d.strain_increment(0, 0) = 2e-4;
  double previous = 0.0;
  for (int n = 0; n < 400; ++n) {
    m->update(d, state);
    EXPECT_GE(state.damage, previous);
    previous = state.damage;
  }
  std::cout << "    damage after shearing " << state.damage << '\n';
  EXPECT_GT(state.damage, 0.0);
  EXPECT_LE(state.damage, 1.0);
}

TEST(MohrCoulomb, InvalidParametersAreRefusedAtTheirKeys) {
  const std::string base =
      "type: mohr_coulomb\ndensity: 2650\nyoungs_modulus: 2.0e7\npoisson_ratio: 0.3\n";
  auto error =
      material_error(base + "friction_angle: 20\nresidual_friction_angle: 30\nsoftening_rate: 5\n");
  EXPECT_EQ(error.where().line, 6);
  EXPECT_NE(std::string(error.what()).find("residual_friction_angle"), std::string::npos);
  error = material_error(base + "friction_angle: 20\nresidual_friction_angle: 10\n");
  EXPECT_EQ(error.where().line, 6);
  EXPECT_NE(std::string(error.what()).find("softening_rate"), std::string::npos);
  error = material_error(base + "friction_angle: 20\ndilation_angle: 25\n");
  EXPECT_EQ(error.where().line, 6);
  error = material_error(base + "friction_angle: 90\n");
  EXPECT_EQ(error.where().line, 5);
  error = material_error(base + "friction_angle: 30\ndilatancy: rowe\ndilation_angle: 5\n");
  EXPECT_EQ(error.where().line, 7);
  error = material_error(base + "friction_angle: 30\ncohesion: -1\n");
  EXPECT_EQ(error.where().line, 6);
  error = material_error(
      base + "friction_angle: 30\ncohesion_degradation: {critical_volumetric_strain: 0}\n");
  EXPECT_EQ(error.where().line, 6);
  error = material_error(
      "type: mohr_coulomb\ndensity: 2650\nyoungs_modulus: 2.0e7\npoisson_ratio: 0.5\n"
      "friction_angle: 30\n");
  EXPECT_EQ(error.where().line, 4);
}

}  // namespace
}  // namespace mpm::testing
