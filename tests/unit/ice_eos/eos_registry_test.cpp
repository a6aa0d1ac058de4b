#include "ice/eos/eos_registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>

#include "cosim/config/document.hpp"
#include "cosim/error.hpp"
#include "ice/eos/ideal_gas.hpp"
#include "ice/eos/linear_water.hpp"
#include "input_error.hpp"

namespace ice::testing {
namespace {

std::unique_ptr<EquationOfState> eos_from_yaml(const std::string& yaml) {
  const auto document = cosim::config::Document::load_string(yaml, "eos.yaml");
  return make_equation_of_state(document.root());
}

// The InputError that building `yaml` throws, printed as a user reads it.
cosim::InputError eos_error(const std::string& yaml) {
  SCOPED_TRACE(yaml);
  return cosim::testing::input_error_from([&] { eos_from_yaml(yaml); });
}

bool mentions(const cosim::InputError& error, const std::string& text) {
  return std::string(error.what()).find(text) != std::string::npos;
}

TEST(EosRegistry, ListsTheBuiltInModels) {
  const auto types = EosRegistry::instance().types();
  for (const char* name : {"ideal_gas", "linear_water"}) {
    EXPECT_NE(std::find(types.begin(), types.end(), name), types.end()) << name;
  }
  const std::string help = EosRegistry::instance().help();
  EXPECT_NE(help.find("gas_constant"), std::string::npos);
  EXPECT_NE(help.find("thermal_expansion"), std::string::npos);
  std::cout << help;
}

TEST(EosRegistry, BuildsAnIdealGasFromEitherHeatParameter) {
  const auto by_ratio =
      eos_from_yaml("type: ideal_gas\ngas_constant: 287.05\nheat_capacity_ratio: 1.4\n");
  ASSERT_EQ(by_ratio->type(), "ideal_gas");
  EXPECT_DOUBLE_EQ(by_ratio->specific_heat(), 287.05 / 0.4);
  EXPECT_DOUBLE_EQ(by_ratio->pressure(1.2, 300.0), 1.2 * 287.05 * 300.0);
  const auto by_cv = eos_from_yaml("type: ideal_gas\ngas_constant: 287.05\nspecific_heat: 718\n");
  EXPECT_DOUBLE_EQ(by_cv->specific_heat(), 718.0);
}

TEST(EosRegistry, BuildsLinearWaterWithDefaultsAndOverrides) {
  const auto w =
      eos_from_yaml("type: linear_water\nbulk_modulus: 2.0e9\nreference_density: 999.8\n");
  ASSERT_EQ(w->type(), "linear_water");
  const auto& water = dynamic_cast<const LinearWater&>(*w);
  EXPECT_DOUBLE_EQ(water.stiffness(), 2.0e9 / 999.8);
  EXPECT_DOUBLE_EQ(water.parameters().reference_pressure, 101325.0);
  EXPECT_DOUBLE_EQ(water.parameters().reference_temperature, 283.15);
  EXPECT_DOUBLE_EQ(water.parameters().thermal_expansion, 2.1e-4);
  const auto custom = eos_from_yaml(
      "type: linear_water\nbulk_modulus: 2.2e9\nreference_density: 1027\nreference_pressure: 0\n"
      "reference_temperature: 277.15\nthermal_expansion: 1.5e-4\nspecific_heat: 3990\n");
  EXPECT_DOUBLE_EQ(custom->pressure(1027.0, 277.15), 0.0);
  EXPECT_DOUBLE_EQ(custom->specific_heat(), 3990.0);
  EXPECT_DOUBLE_EQ(custom->thermal_expansivity(1027.0, 277.15), 1.5e-4);
}

TEST(EosRegistry, UnknownTypeIsRefusedWithASuggestion) {
  const auto error = eos_error("gas_constant: 287\ntype: ideal_gs\n");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_TRUE(mentions(error, "unknown equation of state 'ideal_gs'"));
  EXPECT_TRUE(mentions(error, "did you mean 'ideal_gas'"));
}

TEST(EosRegistry, MissingParametersAreNamed) {
  auto error = eos_error("type: linear_water\nreference_density: 999.8\n");
  EXPECT_TRUE(mentions(error, "bulk_modulus"));
  error = eos_error("type: ideal_gas\nheat_capacity_ratio: 1.4\n");
  EXPECT_TRUE(mentions(error, "gas_constant"));
  error = eos_error("type: ideal_gas\ngas_constant: 287\n");
  EXPECT_TRUE(mentions(error, "specific_heat or heat_capacity_ratio"));
  error = eos_error("bulk_modulus: 2e9\n");
  EXPECT_TRUE(mentions(error, "type"));
}

TEST(EosRegistry, NonPhysicalParametersAreRefusedAtTheirKeys) {
  auto error = eos_error("type: ideal_gas\ngas_constant: 0\nspecific_heat: 718\n");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.key_path(), "gas_constant");
  error = eos_error("type: ideal_gas\ngas_constant: 287\nspecific_heat: -718\n");
  EXPECT_EQ(error.key_path(), "specific_heat");
  error = eos_error("type: ideal_gas\ngas_constant: 287\nheat_capacity_ratio: 1.0\n");
  EXPECT_EQ(error.where().line, 3);
  EXPECT_TRUE(mentions(error, "heat_capacity_ratio must be > 1 (got 1)"));
  error = eos_error(
      "type: ideal_gas\ngas_constant: 287\nspecific_heat: 718\nheat_capacity_ratio: 1.4\n");
  EXPECT_TRUE(mentions(error, "not both"));
  error = eos_error("type: linear_water\nbulk_modulus: -2e9\nreference_density: 999.8\n");
  EXPECT_EQ(error.key_path(), "bulk_modulus");
  error = eos_error("type: linear_water\nbulk_modulus: 2e9\nreference_density: 0\n");
  EXPECT_EQ(error.key_path(), "reference_density");
  error = eos_error(
      "type: linear_water\nbulk_modulus: 2e9\nreference_density: 999.8\nreference_temperature: "
      "0\n");
  EXPECT_EQ(error.key_path(), "reference_temperature");
  error = eos_error(
      "type: linear_water\nbulk_modulus: 2e9\nreference_density: 999.8\nthermal_expansion: -1\n");
  EXPECT_EQ(error.key_path(), "thermal_expansion");
  error = eos_error(
      "type: linear_water\nbulk_modulus: 2e9\nreference_density: 999.8\nthermal_expnsion: 2e-4\n");
  EXPECT_TRUE(mentions(error, "thermal_expansion"));
}

}  // namespace
}  // namespace ice::testing
