#include <gtest/gtest.h>

#include <string>

#include "material_test_support.hpp"

namespace mpm::testing {
namespace {

TEST(MaterialRegistry, ListsTheBuiltInModels) {
  const auto types = MaterialRegistry::instance().types();
  for (const char* name : {"linear_elastic", "neo_hookean", "mohr_coulomb", "drucker_prager"}) {
    EXPECT_NE(std::find(types.begin(), types.end(), name), types.end()) << name;
  }
  const std::string help = MaterialRegistry::instance().help();
  EXPECT_NE(help.find("youngs_modulus"), std::string::npos);
  EXPECT_NE(help.find("residual_friction_angle"), std::string::npos);
  std::cout << help;
}

TEST(MaterialRegistry, UnknownTypeIsRefusedWithASuggestion) {
  const auto error = material_error("density: 2000\ntype: mohr_colomb\n");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_NE(std::string(error.what()).find("did you mean 'mohr_coulomb'"), std::string::npos);
}

TEST(MaterialRegistry, IncompressiblePoissonRatioIsRefusedAtItsKey) {
  const auto error = material_error(
      "type: linear_elastic\ndensity: 2000\nyoungs_modulus: 1.0e7\npoisson_ratio: 0.5\n");
  EXPECT_EQ(error.where().line, 4);
  EXPECT_NE(std::string(error.what()).find("poisson_ratio must be < 0.5 (got 0.5)"),
            std::string::npos);
}

TEST(MaterialRegistry, NonPositiveModulusAndDensityAreRefusedAtTheirKeys) {
  auto error =
      material_error("type: neo_hookean\ndensity: 2000\nyoungs_modulus: 0\npoisson_ratio: 0.3\n");
  EXPECT_EQ(error.where().line, 3);
  EXPECT_NE(std::string(error.what()).find("youngs_modulus"), std::string::npos);
  error = material_error(
      "type: linear_elastic\ndensity: -1\nyoungs_modulus: 1e6\npoisson_ratio: 0.3\n");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_NE(std::string(error.what()).find("density"), std::string::npos);
}

TEST(MaterialRegistry, UnknownKeyIsRefusedWithASuggestion) {
  const auto error = material_error(
      "type: linear_elastic\ndensity: 2000\nyoungs_modulus: 1.0e7\npoisson_ratio: "
      "0.3\nobjective_rat: jaumann\n");
  EXPECT_EQ(error.where().line, 5);
  EXPECT_NE(std::string(error.what()).find("objective_rate"), std::string::npos);
}

TEST(MaterialRegistry, MissingTypeIsRefused) {
  const auto error = material_error("density: 2000\nyoungs_modulus: 1.0e7\n");
  EXPECT_NE(std::string(error.what()).find("type"), std::string::npos);
}

}  // namespace
}  // namespace mpm::testing
