#include "bench/suite.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"
#include "scratch_directory.hpp"

namespace cosim::bench {
namespace {

using cosim::testing::ScratchDirectory;

// The files a small coupled suite refers to.
void write_inputs(const ScratchDirectory& dir) {
  dir.write("soil.yaml", "kind: mpm_case\nname: soil\ndimension: 2\n");
  dir.write("ice.yaml", "kind: ice_case\nname: water\n");
  dir.write("foam.yaml", "kind: openfoam_case\nname: water\n");
  dir.write("ref.csv", "t,v\n0,1\n1,2\n");
}

const char* const coupled_suite = R"(kind: bench_suite
name: small
scenarios:
  - name: column
    soil: soil.yaml
    coupling: {end_time: 1.0, window: 0.1, drag: {law: constant, coefficient: 1.0}}
    backends:
      ice: {fluid: ice.yaml}
      openfoam:
        fluid: foam.yaml
        set: {soil: {grid.cells: [4, 2]}, job: {window: 0.2}}
        full: {set: {fluid: {end_time: 2.0}}}
    not_represented: {swe: "a 1D shallow-water fluid has no pores; measured: none"}
    metrics:
      - name: speed
        unit: m/s
        quantity: {gauge: {name: g, variable: velocity_x, at: end}}
        reference: {analytic: darcy_pore_velocity,
                    parameters: {solid_fraction: 0.6, pressure_drop: 1.0, grain_size: 1.0e-3, length: 1.0}}
        tolerance: {ice: 0.02}
      - name: curve
        quantity: {gauge: {name: g, variable: pressure, at: series}}
        reference: {csv: ref.csv, x: t, y: v}
        error: {norm: max_abs, scale: 2.0, window: [0, 1]}
)";

TEST(Suite, ReadsScenariosBackendsOverridesAndMetrics) {
  ScratchDirectory dir;
  write_inputs(dir);
  const Suite suite = load_suite(dir.write("suite.yaml", coupled_suite));
  ASSERT_EQ(suite.scenarios.size(), 1u);
  const Scenario& s = suite.scenarios[0];
  ASSERT_TRUE(s.coupling.has_value());
  EXPECT_EQ(s.coupling->soil,
            std::filesystem::absolute(dir.path() / "soil.yaml").lexically_normal());
  EXPECT_DOUBLE_EQ(s.coupling->window, 0.1);
  ASSERT_EQ(s.backends.size(), 2u);
  EXPECT_EQ(s.backends[0].backend->name, "ice");
  EXPECT_EQ(s.backends[0].form, InputForm::coupled_fluid);
  const BackendRuns& foam = s.backends[1];
  ASSERT_EQ(foam.overrides.always.size(), 2u);
  EXPECT_EQ(foam.overrides.always[0].role, "soil");
  EXPECT_EQ(foam.overrides.always[0].key_path, "grid.cells");
  EXPECT_EQ(foam.overrides.at(Resolution::coarse).size(), 2u);
  EXPECT_EQ(foam.overrides.at(Resolution::full).size(), 3u);
  ASSERT_EQ(s.metrics.size(), 2u);
  EXPECT_EQ(s.metrics[0].tolerance_for("ice"), 0.02);
  EXPECT_FALSE(s.metrics[0].tolerance_for("openfoam").has_value());
  EXPECT_EQ(s.metrics[1].error.norm, "max_abs");
  EXPECT_DOUBLE_EQ(s.metrics[1].error.scale, 2.0);
  EXPECT_FALSE(s.metrics[1].tolerance_for("ice").has_value());
  ASSERT_EQ(s.not_represented.size(), 1u);
  EXPECT_EQ(s.not_represented[0].backend->name, "swe");
  EXPECT_EQ(s.not_represented[0].reason, "a 1D shallow-water fluid has no pores; measured: none");
}

// Each mistake is refused before anything runs, at its file:line and key.
struct BadSuite {
  const char* what;
  std::string from, to;
  const char* message;
};

class SuiteRefuses : public ::testing::TestWithParam<BadSuite> {};

TEST_P(SuiteRefuses, WithTheFileLineAndKey) {
  ScratchDirectory dir;
  write_inputs(dir);
  std::string text = coupled_suite;
  const auto at = text.find(GetParam().from);
  ASSERT_NE(at, std::string::npos) << GetParam().from;
  text.replace(at, GetParam().from.size(), GetParam().to);
  const auto file = dir.write("suite.yaml", text);
  try {
    load_suite(file);
    FAIL() << GetParam().what << " was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("suite.yaml:"), std::string::npos) << message;
    EXPECT_NE(message.find(GetParam().message), std::string::npos) << message;
    EXPECT_EQ(to_int(e.code()), 2);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Mistakes, SuiteRefuses,
    ::testing::Values(
        BadSuite{"an unknown backend", "      ice: {fluid: ice.yaml}",
                 "      icee: {fluid: ice.yaml}", "unknown backend 'icee'"},
        BadSuite{"two input forms", "      ice: {fluid: ice.yaml}",
                 "      ice: {fluid: ice.yaml, case: ice.yaml}",
                 "exactly one of case, fluid and job"},
        BadSuite{"a missing fluid file", "{fluid: ice.yaml}", "{fluid: nowhere.yaml}",
                 "nowhere.yaml"},
        BadSuite{"a coupled fluid without soil", "    soil: soil.yaml\n", "",
                 "a coupled scenario gives both `soil` and `coupling`"},
        BadSuite{"an override of a role the run lacks",
                 "set: {soil:", "set: {case:", "'case' is not an input of this run"},
        BadSuite{"an unknown analytic solution", "analytic: darcy_pore_velocity", "analytic: darcy",
                 "no analytic solution 'darcy'"},
        BadSuite{"a missing parameter", "pressure_drop: 1.0, ", "",
                 "needs the parameter 'pressure_drop'"},
        BadSuite{"an unknown parameter", "length: 1.0}", "length: 1.0, lenght: 2}",
                 "'lenght' is not a parameter"},
        BadSuite{"a tolerance without reference", "        reference: {csv: ref.csv, x: t, y: v}\n",
                 "        tolerance: 0.1\n", "a tolerance needs a reference"},
        BadSuite{"two quantity kinds",
                 "quantity: {gauge: {name: g, variable: pressure, at: series}}",
                 "quantity: {gauge: {name: g, variable: pressure}, soil: {measure: front}}",
                 "exactly one kind"},
        BadSuite{"a csv reference without its columns", "{csv: ref.csv, x: t, y: v}",
                 "{csv: ref.csv, x: t}", "either `column`"},
        BadSuite{"a negative time", "variable: velocity_x, at: end", "variable: velocity_x, at: -1",
                 "must not be negative"},
        BadSuite{"a reason for a backend that runs",
                 "not_represented: {swe:", "not_represented: {ice:", "'ice' runs the scenario"},
        BadSuite{"a reason for an unknown backend",
                 "not_represented: {swe:", "not_represented: {sve:", "unknown backend 'sve'"},
        BadSuite{"a reason of more than one line", "has no pores; measured",
                 "has no pores\\nmeasured", "say why in one line"},
        BadSuite{"a duplicate metric", "      - name: curve", "      - name: speed",
                 "a second metric named 'speed'"}));

TEST(Suite, MergeKeysShareAMetricsDefinition) {
  ScratchDirectory dir;
  write_inputs(dir);
  const auto file = dir.write("suite.yaml", R"(kind: bench_suite
name: merged
scenarios:
  - name: lake
    backends: {swe: {case: ice.yaml}}
    metrics:
      - &base
        name: a
        quantity: {gauge: {name: g, variable: depth}}
        reference: {value: 1.0}
        tolerance: 0.5
      - <<: *base
        name: b
)");
  const Suite suite = load_suite(file);
  ASSERT_EQ(suite.scenarios[0].metrics.size(), 2u);
  EXPECT_EQ(suite.scenarios[0].metrics[1].name, "b");
  EXPECT_EQ(suite.scenarios[0].metrics[1].tolerance, 0.5);
}

}  // namespace
}  // namespace cosim::bench
