// The swe_case schema is the one place a default is stated: every default is
// a value its own key accepts, a case that leaves a key out reads it, and the
// description built in code starts from the same values.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "schema_default.hpp"
#include "swe/case/case_schema.hpp"
#include "swe/case/load_case.hpp"
#include "swe/scheme.hpp"

namespace swe {
namespace {

template <class T>
T schema_default(const std::string& key_path) {
  return cosim::testing::schema_default<T>(swe_case_schema(), key_path);
}

const char* const bare_case = R"(kind: swe_case
name: bare
dimension: 2
mesh: {origin: [0.0, 0.0], upper: [1.0, 1.0], cells: [10, 10]}
initial: {free_surface: 1.0}
time: {end_time: 1.0}
)";

TEST(SweCaseSchemaDefaults, EveryDefaultIsAcceptedByItsKey) {
  EXPECT_NO_THROW(swe_case_schema().check_defaults());
}

TEST(SweCaseSchemaDefaults, ACaseWithoutTheOptionalKeysReadsTheSchemaDefaults) {
  const CaseDescription c = load_case_text(bare_case, "bare.yaml");
  EXPECT_EQ(c.physics.gravity, schema_default<double>("physics.gravity"));
  EXPECT_EQ(c.physics.density, schema_default<double>("physics.density"));
  EXPECT_EQ(c.physics.manning, schema_default<double>("physics.manning"));
  EXPECT_EQ(c.physics.dry_depth, schema_default<double>("physics.dry_depth"));
  EXPECT_EQ(c.scheme.flux, flux_from_string(schema_default<std::string>("scheme.flux")));
  EXPECT_EQ(c.scheme.limiter, limiter_from_string(schema_default<std::string>("scheme.limiter")));
  EXPECT_EQ(c.scheme.courant, schema_default<double>("scheme.courant"));
  EXPECT_EQ(c.bed.base, schema_default<double>("bed.base"));
  EXPECT_EQ(c.min_time_step, schema_default<double>("time.min_time_step"));
  EXPECT_EQ(c.max_time_step, schema_default<double>("time.max_time_step"));
  EXPECT_EQ(c.window, schema_default<double>("time.window"));
  EXPECT_EQ(c.output_every, schema_default<double>("output.every"));
  EXPECT_EQ(c.snapshots, schema_default<bool>("output.snapshots"));
  EXPECT_EQ(c.gauge_every, schema_default<double>("output.gauge_every"));
  EXPECT_EQ(c.threads, schema_default<int>("threads"));
  EXPECT_TRUE(c.coupling.reads_bed);
  EXPECT_EQ(schema_default<std::vector<std::string>>("coupling.reads"),
            std::vector<std::string>{"bed_elevation"});
  EXPECT_TRUE(c.coupling.writes_traction);
  EXPECT_EQ(schema_default<std::vector<std::string>>("coupling.writes"),
            std::vector<std::string>{"bed_traction"});
  EXPECT_EQ(c.coupling.pressure, BedPressure::hydrostatic);
  EXPECT_EQ(schema_default<std::string>("coupling.bed_pressure"), "hydrostatic");
}

TEST(SweCaseSchemaDefaults, TheDescriptionBuiltInCodeStartsFromTheSchemaDefaults) {
  const CaseDescription c = load_case_text(bare_case, "bare.yaml");
  const CaseDescription in_code;
  EXPECT_EQ(in_code.physics.gravity, c.physics.gravity);
  EXPECT_EQ(in_code.physics.density, c.physics.density);
  EXPECT_EQ(in_code.physics.manning, c.physics.manning);
  EXPECT_EQ(in_code.physics.dry_depth, c.physics.dry_depth);
  EXPECT_EQ(in_code.scheme.flux, c.scheme.flux);
  EXPECT_EQ(in_code.scheme.limiter, c.scheme.limiter);
  EXPECT_EQ(in_code.scheme.courant, c.scheme.courant);
  EXPECT_EQ(in_code.bed.base, c.bed.base);
  EXPECT_EQ(in_code.min_time_step, c.min_time_step);
  EXPECT_EQ(in_code.max_time_step, c.max_time_step);
  EXPECT_EQ(in_code.window, c.window);
  EXPECT_EQ(in_code.output_every, c.output_every);
  EXPECT_EQ(in_code.snapshots, c.snapshots);
  EXPECT_EQ(in_code.gauge_every, c.gauge_every);
  EXPECT_EQ(in_code.threads, c.threads);
  EXPECT_EQ(in_code.coupling.reads_bed, c.coupling.reads_bed);
  EXPECT_EQ(in_code.coupling.writes_traction, c.coupling.writes_traction);
  EXPECT_EQ(in_code.coupling.pressure, c.coupling.pressure);
}

}  // namespace
}  // namespace swe
