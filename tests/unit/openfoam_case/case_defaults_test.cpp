// The openfoam_case schema is the one place a default is stated: every
// default is a value its own key accepts, a case that leaves a key out reads
// it, and the description built in code starts from the same values.

#include <gtest/gtest.h>

#include <string>

#include "openfoam/case/case_schema.hpp"
#include "openfoam/case/load_case.hpp"
#include "schema_default.hpp"

namespace openfoam {
namespace {

template <class T>
T schema_default(const std::string& key_path) {
  return cosim::testing::schema_default<T>(openfoam_case_schema(), key_path);
}

const char* const bare_case = R"(kind: openfoam_case
name: bare
solver: MPPICInterFoam
soil: {}
generate:
  dimension: 2
  grid: {origin: [0.0, 0.0], upper: [0.4, 0.2], cells: [8, 4]}
  fluids:
    water: {density: 1000, viscosity: 1.0e-3}
    air: {density: 1, viscosity: 1.8e-5}
end_time: 0.3
time_step: 1.0e-3
output:
  wave_gauges: [{name: w, x: 0.2}]
)";

TEST(OpenFoamCaseSchemaDefaults, EveryDefaultIsAcceptedByItsKey) {
  EXPECT_NO_THROW(openfoam_case_schema().check_defaults());
}

TEST(OpenFoamCaseSchemaDefaults, ACaseWithoutTheOptionalKeysReadsTheSchemaDefaults) {
  const CaseDescription c = load_case_text(bare_case, "bare.yaml");
  EXPECT_EQ(schema_default<std::string>("solver"), "interFoam");
  EXPECT_EQ(c.output_every, schema_default<double>("output.every"));
  ASSERT_EQ(c.wave_gauges.size(), 1u);
  EXPECT_EQ(c.wave_gauges[0].z, schema_default<double>("output.wave_gauges.[].z"));
  EXPECT_EQ(c.window, c.end_time);  // output.every is 0: one window
  EXPECT_EQ(c.window_timeout, schema_default<double>("window_timeout"));
  EXPECT_EQ(c.keep_time_directories, schema_default<bool>("keep_time_directories"));
  EXPECT_EQ(c.soil.model, SoilModel::parcels);
  EXPECT_EQ(schema_default<std::string>("soil.model"), "parcels");
  EXPECT_EQ(c.soil.zones, schema_default<int>("soil.zones"));
  EXPECT_EQ(c.soil.parcel_density, schema_default<double>("soil.parcel_density"));
  EXPECT_EQ(c.soil.max_solid_fraction, schema_default<double>("soil.max_solid_fraction"));
  EXPECT_EQ(c.soil.minimum_solid_fraction, schema_default<double>("soil.minimum_solid_fraction"));
  EXPECT_EQ(c.soil.displaced_water, schema_default<bool>("soil.displaced_water"));
  ASSERT_TRUE(c.generate);
  EXPECT_EQ(c.generate->surface_tension, schema_default<double>("generate.surface_tension"));
  EXPECT_EQ(c.generate->initial_pressure, schema_default<double>("generate.initial_pressure"));
}

TEST(OpenFoamCaseSchemaDefaults, TheDescriptionBuiltInCodeStartsFromTheSchemaDefaults) {
  const CaseDescription c = load_case_text(bare_case, "bare.yaml");
  const CaseDescription in_code;
  EXPECT_EQ(in_code.solver, schema_default<std::string>("solver"));
  EXPECT_EQ(in_code.output_every, c.output_every);
  EXPECT_EQ(in_code.window_timeout, c.window_timeout);
  EXPECT_EQ(in_code.keep_time_directories, c.keep_time_directories);
  EXPECT_EQ(in_code.soil.model, c.soil.model);
  EXPECT_EQ(in_code.soil.zones, c.soil.zones);
  EXPECT_EQ(in_code.soil.parcel_density, c.soil.parcel_density);
  EXPECT_EQ(in_code.soil.max_solid_fraction, c.soil.max_solid_fraction);
  EXPECT_EQ(in_code.soil.minimum_solid_fraction, c.soil.minimum_solid_fraction);
  EXPECT_EQ(in_code.soil.displaced_water, c.soil.displaced_water);
  const GeneratedCase generated;
  EXPECT_EQ(generated.surface_tension, c.generate->surface_tension);
  EXPECT_EQ(generated.initial_pressure, c.generate->initial_pressure);
}

}  // namespace
}  // namespace openfoam
