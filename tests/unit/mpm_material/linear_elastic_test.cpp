#include <gtest/gtest.h>

#include <random>

#include "material_test_support.hpp"

namespace mpm::testing {
namespace {

const char* const steel =
    "type: linear_elastic\ndensity: 7800\nyoungs_modulus: 2.0e11\npoisson_ratio: 0.25\n";

TEST(LinearElastic, ModuliFromYoungsModulusAndPoissonRatio) {
  const auto m = material_from_yaml(steel);
  const double E = 2.0e11, nu = 0.25;
  EXPECT_EQ(m->type(), "linear_elastic");
  EXPECT_DOUBLE_EQ(m->density(), 7800.0);
  EXPECT_NEAR(m->bulk_modulus(), E / (3.0 * (1.0 - 2.0 * nu)), 1e-6);
  EXPECT_NEAR(m->shear_modulus(), E / (2.0 * (1.0 + nu)), 1e-6);
  EXPECT_FALSE(m->is_hyperelastic());
  EXPECT_EQ(m->objective_rate(), ObjectiveRate::jaumann);
  EXPECT_EQ(m->yield_function(MaterialState{}), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(m->friction_angle(MaterialState{}), 0.0);
}

TEST(LinearElastic, UniaxialStrainGivesTheConstrainedModulus) {
  const auto m = material_from_yaml(steel);
  const double E = 2.0e11, nu = 0.25, eps = 1e-4;
  MaterialState state;
  Deformation d;
  d.strain_increment(0, 0) = eps;
  m->update(d, state);
  const double constrained = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double lateral = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  EXPECT_NEAR(state.stress(0, 0), constrained * eps, 1e-9 * constrained * eps);
  EXPECT_NEAR(state.stress(1, 1), lateral * eps, 1e-9 * constrained * eps);
  EXPECT_NEAR(state.stress(2, 2), lateral * eps, 1e-9 * constrained * eps);
  EXPECT_NEAR(state.stress(0, 1), 0.0, 1e-9 * constrained * eps);
}

TEST(LinearElastic, PureShearAndVolumetricStrainGiveGAndK) {
  const auto m = material_from_yaml(steel);
  MaterialState state;
  Deformation d;
  d.strain_increment(0, 1) = d.strain_increment(1, 0) = 1e-4;
  m->update(d, state);
  EXPECT_NEAR(state.stress(0, 1), 2.0 * m->shear_modulus() * 1e-4, 1e-3);
  EXPECT_NEAR(state.stress.trace(), 0.0, 1e-3);
  MaterialState pressed;
  d.strain_increment = -1e-4 / 3.0 * Tensor::Identity();
  m->update(d, pressed);
  EXPECT_NEAR(pressed.stress.trace() / 3.0, -m->bulk_modulus() * 1e-4, 1e-3);
}

TEST(LinearElastic, RotatedInputsGiveTheRotatedStress) {
  const auto m = material_from_yaml(steel);
  std::mt19937 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const Tensor Q = random_rotation(rng);
    MaterialState a, b;
    a.stress = random_symmetric(rng, 1e6);
    b.stress = Q * a.stress * Q.transpose();
    Deformation da, db;
    da.strain_increment = random_symmetric(rng, 1e-4);
    db.strain_increment = Q * da.strain_increment * Q.transpose();
    m->update(da, a);
    m->update(db, b);
    EXPECT_LT(relative_difference(Q * a.stress * Q.transpose(), b.stress), 1e-13);
  }
}

TEST(LinearElastic, PolarRotationIsSelectable) {
  const auto m = material_from_yaml(std::string(steel) + "objective_rate: polar_rotation\n");
  EXPECT_EQ(m->objective_rate(), ObjectiveRate::polar_rotation);
}

}  // namespace
}  // namespace mpm::testing
