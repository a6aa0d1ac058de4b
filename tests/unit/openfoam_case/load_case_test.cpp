#include "openfoam/case/load_case.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"
#include "input_error.hpp"
#include "replaced_text.hpp"

using cosim::testing::replaced;

namespace openfoam {
namespace {

const std::string dam_break = R"(kind: openfoam_case
name: dam
generate:
  dimension: 2
  grid: {origin: [0.0, 0.0], upper: [0.4, 0.2], cells: [8, 4]}
  gravity: [0.0, -9.81]
  fluids:
    water: {density: 1000, viscosity: 1.0e-3}
    air: {density: 1, viscosity: 1.8e-5}
  water:
    - box: {lower: [0.0, 0.0], upper: [0.1, 0.1]}
  boundaries: {x_max: slip, y_max: atmosphere}
end_time: 0.3
time_step: 1.0e-3
window: 0.01
output: {every: 0.05}
)";

std::string error_of(const std::string& text) {
  return cosim::testing::input_error_message([&] { load_case_text(text, "case.yaml"); });
}

TEST(OpenFoamCase, ReadsEveryKeyAndTheDefaults) {
  const CaseDescription c = load_case_text(dam_break, "case.yaml");
  EXPECT_EQ(c.name, "dam");
  EXPECT_EQ(c.solver, "interFoam");
  ASSERT_TRUE(c.generate.has_value());
  const GeneratedCase& g = *c.generate;
  EXPECT_EQ(g.dimension, 2);
  EXPECT_EQ(g.cells[0], 8);
  EXPECT_EQ(g.cells[1], 4);
  EXPECT_EQ(g.cells[2], 1);
  // 2D: one cell thick, as thick as the smallest spacing (0.05).
  EXPECT_DOUBLE_EQ(g.upper[2] - g.origin[2], 0.05);
  EXPECT_DOUBLE_EQ(g.gravity[1], -9.81);
  EXPECT_DOUBLE_EQ(g.water.density, 1000.0);
  EXPECT_DOUBLE_EQ(g.air.viscosity, 1.8e-5);
  EXPECT_DOUBLE_EQ(g.surface_tension, 0.07);
  ASSERT_EQ(g.water_regions.size(), 1u);
  EXPECT_DOUBLE_EQ(g.water_regions[0].upper[0], 0.1);
  EXPECT_EQ(g.sides[0], SideKind::wall);
  EXPECT_EQ(g.sides[1], SideKind::slip);
  EXPECT_EQ(g.sides[3], SideKind::atmosphere);
  EXPECT_DOUBLE_EQ(c.window, 0.01);
  EXPECT_DOUBLE_EQ(c.output_every, 0.05);
  EXPECT_FALSE(c.keep_time_directories);
  EXPECT_NE(c.config_hash, 0u);
}

TEST(OpenFoamCase, ReadsPressureSidesTheSoilsCloudAndGauges) {
  std::string text = replaced(dam_break, "boundaries: {x_max: slip, y_max: atmosphere}",
                              "boundaries: {x_min: {pressure: 1.5e5}, x_max: slip}\n"
                              "  initial_pressure: 101325");
  text = replaced(text, "name: dam\n",
                  "name: dam\nsolver: MPPICInterFoam\nsoil: {parcel_density: 1.0e7}\n");
  text = replaced(text, "output: {every: 0.05}",
                  "output: {every: 0.05, gauges: [{name: g1, point: [0.2, 0.05]}]}");
  const CaseDescription c = load_case_text(text, "case.yaml");
  EXPECT_TRUE(c.has_cloud());
  EXPECT_DOUBLE_EQ(c.soil.parcel_density, 1.0e7);
  EXPECT_DOUBLE_EQ(c.soil.max_solid_fraction, 0.99);
  EXPECT_EQ(c.generate->sides[0], SideKind::pressure);
  EXPECT_DOUBLE_EQ(c.generate->side_pressure[0], 1.5e5);
  EXPECT_DOUBLE_EQ(c.generate->initial_pressure, 101325.0);
  ASSERT_EQ(c.gauges.size(), 1u);
  EXPECT_EQ(c.gauges[0].name, "g1");
  EXPECT_DOUBLE_EQ(c.gauges[0].point[0], 0.2);
}

TEST(OpenFoamCase, TheWindowDefaultsToTheSnapshotInterval) {
  const CaseDescription c = load_case_text(replaced(dam_break, "window: 0.01\n", ""), "case.yaml");
  EXPECT_DOUBLE_EQ(c.window, 0.05);
}

struct BadCase {
  const char* name;
  const char* from;
  const char* to;
  const char* says;  // part of the message
};

class OpenFoamCaseErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(OpenFoamCaseErrors, NameTheFileTheKeyAndTheLine) {
  const BadCase& bad = GetParam();
  const std::string message = error_of(replaced(dam_break, bad.from, bad.to));
  EXPECT_NE(message.find("case.yaml:"), std::string::npos) << message;
  EXPECT_NE(message.find(bad.says), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, OpenFoamCaseErrors,
    ::testing::Values(
        BadCase{"window_not_whole_steps", "window: 0.01", "window: 0.0105",
                "not a whole number of time steps"},
        BadCase{"output_not_whole_steps", "every: 0.05", "every: 0.0505",
                "not a whole number of time steps"},
        BadCase{"end_not_whole_steps", "end_time: 0.3", "end_time: 0.3004",
                "not a whole number of time steps"},
        BadCase{"step_longer_than_run", "time_step: 1.0e-3", "time_step: 1.0", "longer than"},
        BadCase{"no_case", "generate:", "generated:", "generated"},
        BadCase{"both_cases", "end_time: 0.3", "directory: .\nend_time: 0.3",
                "either `generate` or `directory`"},
        BadCase{"fractional_cells", "cells: [8, 4]", "cells: [8.5, 4]", "whole number"},
        BadCase{"wrong_dimension_vector", "upper: [0.4, 0.2]", "upper: [0.4, 0.2, 0.1]",
                "expected 2 values"},
        BadCase{"inverted_box", "upper: [0.1, 0.1]", "upper: [0.1, -0.1]", "not above"},
        BadCase{"unknown_side", "x_max: slip", "x_max: porous", "porous"},
        BadCase{"empty_side_in_2d", "x_max: slip", "z_max: slip", "empty front and back"},
        BadCase{"negative_density", "density: 1000", "density: -1000", "density"},
        BadCase{"soil_without_cloud_solver", "end_time: 0.3", "soil: {}\nend_time: 0.3",
                "needs `solver: MPPICInterFoam`"},
        BadCase{"pressure_side_without_value", "x_max: slip", "x_max: {pressur: 1}", "pressur"}),
    [](const ::testing::TestParamInfo<BadCase>& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace openfoam
