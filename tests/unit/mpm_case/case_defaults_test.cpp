// The case schema is the one place a default is stated: every default is a
// value its own key accepts, and a case that leaves a key out reads it.

#include <gtest/gtest.h>

#include <string>

#include "mpm/case/case_schema.hpp"
#include "mpm/case/load_case.hpp"
#include "mpm/material/material_registry.hpp"
#include "schema_default.hpp"

namespace mpm {
namespace {

template <class T>
T schema_default(const std::string& key_path) {
  return cosim::testing::schema_default<T>(mpm_case_schema(), key_path);
}

const char* const bare_case = R"(kind: mpm_case
dimension: 2
grid: {origin: [0, 0], upper: [1, 1], cells: [10, 10]}
time: {end_time: 0.1}
materials:
  rubber: {type: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
bodies:
  - name: block
    material: rubber
    geometry: {box: {min: [0.4, 0.4], max: [0.6, 0.6]}}
loads:
  - {name: top, body: block, region: {min: [0.4, 0.55], max: [0.6, 0.6]}, pressure: 1000}
)";

TEST(MpmCaseSchemaDefaults, EveryDefaultIsAcceptedByItsKey) {
  EXPECT_NO_THROW(mpm_case_schema().check_defaults());
  const auto& materials = MaterialRegistry::instance();
  for (const std::string& type : materials.types()) {
    EXPECT_NO_THROW(materials.schema(type).check_defaults()) << type;
  }
}

TEST(MpmCaseSchemaDefaults, ACaseWithoutTheOptionalKeysReadsTheSchemaDefaults) {
  const CaseDescription c = load_case_text(bare_case, "bare.yaml");
  EXPECT_EQ(c.time.safety_factor, schema_default<double>("time.safety_factor"));
  EXPECT_EQ(c.time.min_time_step, schema_default<double>("time.min_time_step"));
  EXPECT_EQ(c.flip_fraction, schema_default<double>("flip_fraction"));
  EXPECT_EQ(c.shape, ShapeKind::gimp);
  EXPECT_EQ(schema_default<std::string>("shape"), "gimp");
  EXPECT_EQ(c.scheme, UpdateScheme::musl);
  EXPECT_EQ(schema_default<std::string>("scheme"), "musl");
  EXPECT_EQ(c.locking, LockingMitigation::none);
  EXPECT_EQ(schema_default<std::string>("locking"), "none");
  EXPECT_EQ(c.gimp_domain, GimpDomain::initial);
  EXPECT_EQ(schema_default<std::string>("gimp_domain"), "initial");
  EXPECT_EQ(c.gravity_ramp_time, schema_default<double>("gravity_ramp_time"));
  EXPECT_EQ(c.damping, schema_default<double>("damping"));
  EXPECT_EQ(c.threads, schema_default<int>("threads"));
  EXPECT_EQ(c.contact.enabled, schema_default<bool>("contact.enabled"));
  EXPECT_EQ(c.contact.friction, schema_default<double>("contact.friction"));
  EXPECT_EQ(c.output.every, schema_default<double>("output.every"));
  EXPECT_EQ(c.output.grid, schema_default<bool>("output.grid"));
  EXPECT_EQ(c.output.probe_every, schema_default<double>("output.probe_every"));
  ASSERT_EQ(c.bodies.size(), 1u);
  EXPECT_EQ(c.bodies[0].initial_temperature, schema_default<double>("bodies.[].temperature"));
  ASSERT_EQ(c.loads.size(), 1u);
  EXPECT_EQ(c.loads[0].face, 3);
  EXPECT_EQ(schema_default<std::string>("loads.[].face"), "y_max");
  EXPECT_EQ(c.loads[0].ramp_time, schema_default<double>("loads.[].ramp_time"));
  EXPECT_EQ(c.loads[0].ramp_shape, LoadSpec::RampShape::linear);
  EXPECT_EQ(schema_default<std::string>("loads.[].ramp_shape"), "linear");
}

}  // namespace
}  // namespace mpm
