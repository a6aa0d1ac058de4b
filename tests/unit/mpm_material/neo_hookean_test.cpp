#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "material_test_support.hpp"
#include "mpm/material/elastic_constants.hpp"

namespace mpm::testing {
namespace {

const char* const rubber =
    "type: neo_hookean\ndensity: 1100\nyoungs_modulus: 1.0e6\npoisson_ratio: 0.3\n";

TEST(NeoHookean, IsHyperelasticWithTheSmallStrainModuli) {
  const auto m = material_from_yaml(rubber);
  const auto e = ElasticConstants::from_youngs_poisson(1.0e6, 0.3);
  EXPECT_TRUE(m->is_hyperelastic());
  EXPECT_NEAR(m->bulk_modulus(), e.bulk, 1e-9);
  EXPECT_NEAR(m->shear_modulus(), e.shear, 1e-9);
}

// Uniaxial stretch F = diag(s, 1, 1): MPMICE eq. 15 in closed form.
TEST(NeoHookean, FiniteUniaxialStretchMatchesTheClosedForm) {
  const auto m = material_from_yaml(rubber);
  const auto e = ElasticConstants::from_youngs_poisson(1.0e6, 0.3);
  const double lambda = e.lame(), mu = e.shear;
  for (const double s : {0.5, 0.8, 1.0, 1.3, 2.0}) {
    MaterialState state;
    Deformation d;
    d.deformation_gradient = Eigen::Vector3d(s, 1.0, 1.0).asDiagonal();
    m->update(d, state);
    const double J = s;
    const double axial = lambda * std::log(J) / J + mu / J * (s * s - 1.0);
    const double lateral = lambda * std::log(J) / J;
    EXPECT_NEAR(state.stress(0, 0), axial, 1e-9 * mu) << "stretch " << s;
    EXPECT_NEAR(state.stress(1, 1), lateral, 1e-9 * mu) << "stretch " << s;
    EXPECT_NEAR(state.stress(2, 2), lateral, 1e-9 * mu) << "stretch " << s;
    EXPECT_NEAR(state.stress(0, 1), 0.0, 1e-9 * mu);
  }
}

TEST(NeoHookean, SmallStrainLimitIsHooke) {
  const auto m = material_from_yaml(rubber);
  const auto e = ElasticConstants::from_youngs_poisson(1.0e6, 0.3);
  std::mt19937 rng(5);
  const Tensor eps = random_symmetric(rng, 1e-7);
  MaterialState state;
  Deformation d;
  d.deformation_gradient = Tensor::Identity() + eps;
  m->update(d, state);
  const Tensor hooke = e.stress_increment(eps);
  EXPECT_LT(relative_difference(state.stress, hooke), 1e-5);
}

TEST(NeoHookean, RotatingTheDeformationRotatesTheStress) {
  const auto m = material_from_yaml(rubber);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Tensor Q = random_rotation(rng);
    Deformation d;
    d.deformation_gradient = Tensor::Identity() + random_matrix(rng, 0.3);
    MaterialState a, b;
    m->update(d, a);
    d.deformation_gradient = Q * d.deformation_gradient;
    m->update(d, b);
    EXPECT_LT(relative_difference(Q * a.stress * Q.transpose(), b.stress), 1e-12);
  }
}

}  // namespace
}  // namespace mpm::testing
