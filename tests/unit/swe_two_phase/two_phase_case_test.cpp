#include <gtest/gtest.h>

#include <string>

#include "input_error.hpp"
#include "replaced_text.hpp"
#include "schema_default.hpp"
#include "swe/case/case_schema.hpp"
#include "swe/case/load_case.hpp"

namespace swe {
namespace {

using cosim::testing::replaced;

const std::string two_phase_case = R"(kind: swe_case
name: slide_in_lake
dimension: 2
mesh: {origin: [0.0, 0.0], upper: [4.0, 4.0], cells: [4, 4]}
initial: {free_surface: 1.0}
time: {end_time: 1.0}
two_phase:
  drag:
    exponent_j: 2
    smoothing_speed: 0.5
  virtual_mass: false
  solid_layer: {depth: 0.4, density: 2000, velocity: [1.0, 0.0], box: {min: [0.0, 0.0], max: [2.0, 4.0]}}
)";

std::string error_of(const std::string& text) {
  return cosim::testing::input_error_message([&] { load_case_text(text, "case.yaml"); });
}

TEST(SweTwoPhaseCase, ReadsTheBlockAndLaysTheWaterOverTheSolids) {
  const CaseDescription c = load_case_text(two_phase_case, "case.yaml");
  ASSERT_TRUE(c.two_phase);
  EXPECT_EQ(c.two_phase->parameters.drag.exponent, 2.0);
  EXPECT_EQ(*c.two_phase->parameters.drag.smoothing_speed, 0.5);
  EXPECT_FALSE(c.two_phase->parameters.virtual_mass);
  ASSERT_TRUE(c.two_phase->initial_layer);
  EXPECT_EQ(c.two_phase->initial_layer->depth, 0.4);
  const auto solver = make_solver(c);
  // cell 0 (x = 0.5) under the layer, cell 3 (x = 3.5) not: the free surface stays at 1
  EXPECT_DOUBLE_EQ(solver->bed()[0], 0.4);
  EXPECT_DOUBLE_EQ(solver->depth()[0], 0.6);
  EXPECT_DOUBLE_EQ(solver->depth()[3], 1.0);
}

TEST(SweTwoPhaseCase, DefaultsAreTheStructsDefaults) {
  const CaseDescription c = load_case_text(
      replaced(two_phase_case,
               "  drag:\n    exponent_j: 2\n    smoothing_speed: 0.5\n  virtual_mass: false\n", ""),
      "case.yaml");
  const TwoPhaseParameters p;
  auto d = [](const char* key) {
    return cosim::testing::schema_default<double>(swe_case_schema(), key);
  };
  EXPECT_EQ(c.two_phase->parameters.drag.exponent, p.drag.exponent);
  EXPECT_EQ(d("two_phase.drag.exponent_j"), p.drag.exponent);
  EXPECT_EQ(d("two_phase.drag.reynolds_exponent_M"), p.drag.reynolds_exponent);
  EXPECT_EQ(d("two_phase.drag.partition_exponent_m"), p.drag.partition_exponent);
  EXPECT_EQ(d("two_phase.drag.grain_size"), p.drag.grain_size);
  EXPECT_EQ(d("two_phase.drag.block_size"), p.drag.block_size);
  EXPECT_EQ(d("two_phase.solid_density"), p.solid_density);
  EXPECT_EQ(d("two_phase.fluid_viscosity"), p.fluid_viscosity);
  EXPECT_EQ(c.two_phase->parameters.virtual_mass, p.virtual_mass);
  EXPECT_FALSE(c.two_phase->parameters.drag.smoothing_speed);
  EXPECT_NO_THROW(swe_case_schema().check_defaults());
}

TEST(SweTwoPhaseCase, RefusesOutOfRangeValuesAtTheirKeyAndLine) {
  std::string message = error_of(replaced(two_phase_case, "exponent_j: 2", "exponent_j: 3"));
  EXPECT_NE(message.find("case.yaml:9"), std::string::npos) << message;
  EXPECT_NE(message.find("two_phase.drag.exponent_j"), std::string::npos) << message;
  EXPECT_NE(message.find("exponent j"), std::string::npos) << message;
  message = error_of(replaced(two_phase_case, "smoothing_speed: 0.5", "smoothing_speed: -1"));
  EXPECT_NE(message.find("case.yaml:10"), std::string::npos) << message;
  message = error_of(replaced(two_phase_case, "density: 2000", "density: 3000"));
  EXPECT_NE(message.find("two_phase.solid_layer.density"), std::string::npos) << message;
  message = error_of(replaced(
      two_phase_case, "dimension: 2\nmesh: {origin: [0.0, 0.0], upper: [4.0, 4.0], cells: [4, 4]}",
      "dimension: 1\nmesh: {from: 0.0, to: 4.0, cells: 4}"));
  EXPECT_NE(message.find("two-phase"), std::string::npos) << message;
}

TEST(SweTwoPhaseCase, HelpStatesTheMeaningOfJ) {
  const std::string help = swe_case_help();
  EXPECT_NE(help.find("j = 1 is linear"), std::string::npos);
}

}  // namespace
}  // namespace swe
