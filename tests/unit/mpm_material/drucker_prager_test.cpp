#include "mpm/material/drucker_prager.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "material_test_support.hpp"

namespace mpm::testing {
namespace {

constexpr double deg = std::numbers::pi / 180.0;
constexpr double sqrt2 = std::numbers::sqrt2;

ElasticConstants soil_elasticity() {
  return ElasticConstants::from_youngs_poisson(2.0e7, 0.3);
}

double mean(const Tensor& t) {
  return t.trace() / 3.0;
}
Tensor deviator(const Tensor& t) {
  return t - mean(t) * Tensor::Identity();
}
double sqrt_j2(const Tensor& t) {
  return std::sqrt(0.5 * deviator(t).squaredNorm());
}

TEST(DruckerPragerCone, PlaneStrainMatchIsVanDenBoutEq20) {
  const double phi = 30 * deg, c = 1e4;
  const auto cone =
      DruckerPragerCone::matched(DruckerPragerMatch::plane_strain, phi, 0.0, c, 1e300);
  const double root = std::sqrt(9 + 12 * std::tan(phi) * std::tan(phi));
  EXPECT_DOUBLE_EQ(cone.alpha_friction, std::tan(phi) / root);
  EXPECT_DOUBLE_EQ(cone.strength, 3 * c / root);
  EXPECT_EQ(cone.alpha_dilation, 0.0);
}

// The compression cone passes through the Mohr-Coulomb triaxial compression
// states (sigma_1 = sigma_2 > sigma_3), the extension cone through the
// extension states (sigma_1 > sigma_2 = sigma_3).
TEST(DruckerPragerCone, ConesPassThroughTheMohrCoulombMeridians) {
  const double phi = 35 * deg, c = 2e4, s = std::sin(phi);
  const auto compression =
      DruckerPragerCone::matched(DruckerPragerMatch::compression_cone, phi, 0.0, c, 1e300);
  const auto extension =
      DruckerPragerCone::matched(DruckerPragerMatch::extension_cone, phi, 0.0, c, 1e300);
  for (const double confining : {-1e4, -1e5, -1e6}) {
    // MC: (1 + s) s1 - (1 - s) s3 = 2 c cos phi.
    const double major =
        ((1 + s) * confining - 2 * c * std::cos(phi)) / (1 - s);  // sigma_3 at sigma_1 = confining
    Tensor tc = Eigen::Vector3d(confining, confining, major).asDiagonal();
    EXPECT_NEAR(compression.yield(tc) / std::abs(major), 0.0, 1e-12);
    const double minor =
        ((1 - s) * confining + 2 * c * std::cos(phi)) / (1 + s);  // sigma_1 at sigma_3 = confining
    Tensor te = Eigen::Vector3d(minor, confining, confining).asDiagonal();
    EXPECT_NEAR(extension.yield(te) / std::abs(confining), 0.0, 1e-12);
  }
}

// Random trials: the stress ends on or inside cone and cut-off; a cone return
// has plastic strain along dg/dsigma = alpha_psi I + s / (2 sqrt J2).
TEST(DruckerPragerReturn, RandomTrialsEndOnTheSurfaceWithFlowAlongThePotential) {
  const auto e = soil_elasticity();
  std::mt19937 rng(23);
  std::map<std::string, int> hits;
  for (const double t : {std::numeric_limits<double>::infinity(), 3e3}) {
    for (const double psi : {0.0, 10 * deg, 30 * deg}) {
      const auto cone =
          DruckerPragerCone::matched(DruckerPragerMatch::plane_strain, 30 * deg, psi, 1e4, t);
      double worst = 0.0;
      for (int n = 0; n < 3000; ++n) {
        std::uniform_real_distribution<double> u(0.0, 1.0);
        const double shear = 1e5 * std::pow(u(rng), 3.0);
        const Tensor trial =
            random_symmetric(rng, shear) + (-2e5 + 2.5e5 * u(rng)) * Tensor::Identity();
        const Tensor sigma = drucker_prager_return(trial, cone, e);
        const double scale = std::max(1e4, trial.norm());
        worst = std::max(worst, cone.yield(sigma) / scale);
        EXPECT_LE(cone.yield(sigma), 1e-10 * scale);
        if (sigma == trial) {
          ++hits["elastic"];
          continue;
        }
        const Tensor strain = e.strain_increment(trial - sigma);
        const double f = 3 * cone.alpha_friction * mean(sigma) + sqrt_j2(sigma) - cone.strength;
        const bool on_cone = std::abs(f) <= 1e-9 * scale;
        const bool on_cutoff = std::abs(mean(sigma) - cone.mean_stress_limit()) <= 1e-9 * scale;
        if (on_cone && !on_cutoff) {
          ++hits["cone"];
          // dev(d eps^p) along s, and tr / |dev| = 3 sqrt2 alpha_psi.
          const Tensor dev = deviator(strain);
          const Tensor direction = deviator(sigma) / deviator(sigma).norm();
          EXPECT_LT((dev - dev.norm() * direction).norm(), 1e-8 * dev.norm());
          EXPECT_NEAR(strain.trace() / dev.norm(), 3 * sqrt2 * cone.alpha_dilation, 1e-8);
        } else if (on_cutoff && !on_cone) {
          ++hits["cut-off"];
          EXPECT_LT(deviator(strain).norm(), 1e-9 * strain.norm());  // flow normal to p = sigma_t
        } else {
          ASSERT_TRUE(on_cone && on_cutoff);
          ++hits[std::isfinite(t) ? "corner" : "apex"];
          // s shrinks along itself; the mean stress falls to the limit.
          EXPECT_LT((deviator(sigma) - sqrt_j2(sigma) / sqrt_j2(trial) * deviator(trial)).norm(),
                    1e-9 * scale);
        }
      }
      std::cout << "    psi " << psi / deg << " t " << t << ": worst f/|sigma| " << worst
                << " (tolerance 1e-10)\n";
    }
  }
  for (const auto& [name, count] : hits) std::cout << "    " << name << ": " << count << '\n';
  for (const char* region : {"elastic", "cone", "cut-off", "corner", "apex"})
    EXPECT_GT(hits[region], 10) << region;
}

const char* const clay =
    "type: drucker_prager\ndensity: 2000\nyoungs_modulus: 2.0e7\npoisson_ratio: "
    "0.3\nfriction_angle: 30\n"
    "dilation_angle: 10\ncohesion: 1.0e4\n";

TEST(DruckerPrager, RandomStepsAreFrameIndifferent) {
  const auto m = material_from_yaml(clay);
  std::mt19937 rng(29);
  int plastic = 0;
  for (int n = 0; n < 1000; ++n) {
    const Tensor Q = random_rotation(rng);
    MaterialState a;
    a.stress = random_symmetric(rng, 2e4) - 4e4 * Tensor::Identity();
    MaterialState b = a;
    b.stress = Q * a.stress * Q.transpose();
    Deformation da, db;
    da.strain_increment = random_symmetric(rng, 3e-3);
    db.strain_increment = Q * da.strain_increment * Q.transpose();
    m->update(da, a);
    m->update(db, b);
    EXPECT_LT((Q * a.stress * Q.transpose() - b.stress).norm(),
              1e-9 * std::max(1e4, a.stress.norm()));
    EXPECT_LE(m->yield_function(a), 1e-8 * std::max(1e4, a.stress.norm()));
    plastic += a.plastic_strain > 0.0;
  }
  EXPECT_GT(plastic, 100);
}

// Associated plane-strain flow at the plane-strain match ends on the
// Mohr-Coulomb criterion in the plane: (s1 - s3) / 2 = c cos phi - (s1 + s3) / 2 sin phi.
// The strain increments are those of steady associated flow with no
// out-of-plane plastic strain: d eps_xx + d eps_yy = 3 alpha mu and
// d eps_xx - d eps_yy = sqrt(1 - 3 alpha^2) mu.
TEST(DruckerPrager, AssociatedPlaneStrainLimitIsMohrCoulomb) {
  const auto m = material_from_yaml(
      "type: drucker_prager\ndensity: 2000\nyoungs_modulus: 2.0e7\npoisson_ratio: "
      "0.3\nfriction_angle: 30\n"
      "dilation_angle: 30\ncohesion: 1.0e4\n");
  MaterialState state;
  state.stress = -1e5 * Tensor::Identity();
  Deformation d;
  const double alpha =
      std::tan(30 * deg) / std::sqrt(9 + 12 * std::tan(30 * deg) * std::tan(30 * deg));
  const double mu = 1e-4, sum = 3 * alpha * mu, difference = std::sqrt(1 - 3 * alpha * alpha) * mu;
  d.strain_increment(0, 0) = 0.5 * (sum + difference);
  d.strain_increment(1, 1) = 0.5 * (sum - difference);
  for (int n = 0; n < 3000; ++n) m->update(d, state);
  const double s1 = state.stress(0, 0), s3 = state.stress(1, 1);
  const double radius = 0.5 * (s1 - s3), centre = 0.5 * (s1 + s3);
  const double mc = 1e4 * std::cos(30 * deg) - centre * std::sin(30 * deg);
  std::cout << "    in-plane radius " << radius << ", Mohr-Coulomb " << mc << ", relative error "
            << (radius - mc) / mc << " (tolerance 1e-4)\n";
  EXPECT_NEAR(radius / mc, 1.0, 1e-4);
}

TEST(DruckerPrager, MatchKeySelectsTheCone) {
  const auto a = material_from_yaml(std::string(clay) + "match: compression_cone\n");
  const auto b = material_from_yaml(std::string(clay) + "match: extension_cone\n");
  MaterialState state;
  state.stress = Eigen::Vector3d(-1e5, -1e5, -3.2e5).asDiagonal();
  EXPECT_GT(b->yield_function(state), a->yield_function(state));
  EXPECT_NEAR(a->friction_angle(state), 30 * deg, 1e-15);
  const auto error = material_error(std::string(clay) + "match: plain_strain\n");
  EXPECT_NE(std::string(error.what()).find("plane_strain"), std::string::npos);
}

}  // namespace
}  // namespace mpm::testing
