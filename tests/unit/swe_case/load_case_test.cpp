#include "swe/case/load_case.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"
#include "input_error.hpp"
#include "replaced_text.hpp"

using cosim::testing::replaced;

namespace {

const std::string stoker = R"(kind: swe_case
name: stoker
dimension: 1
mesh:
  from: 0.0
  segments:
    - {to: 0.25, width: 0.03}
    - {to: 0.75, width: 0.016}
    - {to: 1.0, width: 0.03}
initial:
  depth: 0.5
  regions:
    - {box: {min: [0.0], max: [0.5]}, depth: 1.0}
boundaries: {left: transmissive, right: {fixed_depth: 0.5}}
time: {end_time: 0.1}
output:
  gauges:
    - {name: dam, x: 0.5}
)";

// The message of the InputError that loading `text` throws.
std::string error_of(const std::string& text) {
  return cosim::testing::input_error_message([&] { swe::load_case_text(text, "case.yaml"); });
}

TEST(SweCase, BuildsNonUniformSegmentsThatFitTheirStretchesExactly) {
  const swe::CaseDescription c = swe::load_case_text(stoker, "case.yaml");
  // round(0.25 / 0.03) = 8, round(0.5 / 0.016) = 31, 8 again.
  ASSERT_EQ(c.edges.size(), 8u + 31u + 8u + 1u);
  EXPECT_DOUBLE_EQ(c.edges[8], 0.25);
  EXPECT_DOUBLE_EQ(c.edges[39], 0.75);
  EXPECT_DOUBLE_EQ(c.edges.back(), 1.0);
  EXPECT_EQ(c.boundaries_1d.left.kind, swe::BoundaryKind::transmissive);
  EXPECT_EQ(c.boundaries_1d.right.kind, swe::BoundaryKind::fixed_depth);
  EXPECT_DOUBLE_EQ(c.boundaries_1d.right.value, 0.5);
  ASSERT_EQ(c.gauges.size(), 1u);
}

TEST(SweCase, LaysTheWaterOverTheBed) {
  const std::string text = R"(kind: swe_case
name: lake
dimension: 1
mesh: {from: 0.0, to: 4.0, cells: 4}
bed: {base: 0.1, profile: [[0.0, 0.0], [4.0, 0.8]]}
initial: {free_surface: 0.5, velocity: [0.2]}
time: {end_time: 1.0}
)";
  const auto solver = swe::make_solver(swe::load_case_text(text, "lake.yaml"));
  const auto h = solver->depth();
  const auto b = solver->bed();
  // Centres 0.5, 1.5, 2.5, 3.5: B = 0.1 + 0.2 x; h = max(0, 0.5 - B).
  EXPECT_NEAR(b[0], 0.2, 1e-15);
  EXPECT_NEAR(h[0], 0.3, 1e-15);
  EXPECT_NEAR(h[1], 0.1, 1e-15);
  EXPECT_EQ(h[2], 0.0);
  EXPECT_EQ(h[3], 0.0);
  EXPECT_NEAR(solver->discharge_x()[0], 0.06, 1e-15);
  EXPECT_EQ(solver->discharge_x()[3], 0.0);
}

TEST(SweCase, CirclesAndBoxesSetWaterIn2D) {
  const std::string text = R"(kind: swe_case
name: radial
dimension: 2
mesh: {origin: [-1.0, -1.0], upper: [1.0, 1.0], cells: [4, 4]}
initial:
  depth: 0.5
  regions:
    - {circle: {centre: [0.0, 0.0], radius: 0.5}, depth: 1.0}
time: {end_time: 1.0}
output: {gauges: [{name: corner, position: [0.9, -0.9]}]}
)";
  const auto solver = swe::make_solver(swe::load_case_text(text, "radial.yaml"));
  const auto h = solver->depth();
  ASSERT_EQ(h.size(), 16u);
  EXPECT_EQ(h[0], 0.5);   // corner cell centre (-0.75, -0.75)
  EXPECT_EQ(h[5], 1.0);   // centre (-0.25, -0.25)
  EXPECT_EQ(h[10], 1.0);  // (0.25, 0.25)
}

TEST(SweCase, RefusesANegativeInitialDepthAtItsLine) {
  const std::string message = error_of(replaced(stoker, "depth: 1.0}", "depth: -1.0}"));
  EXPECT_NE(message.find("case.yaml:13"), std::string::npos) << message;
  EXPECT_NE(message.find("depth"), std::string::npos) << message;
}

TEST(SweCase, RefusesCellsOfZeroOrNegativeWidth) {
  std::string message =
      error_of(replaced(stoker, "{to: 0.75, width: 0.016}", "{to: 0.2, width: 0.016}"));
  EXPECT_NE(message.find("segments[1].to"), std::string::npos) << message;
  EXPECT_NE(message.find("case.yaml:8"), std::string::npos) << message;
  message = error_of(replaced(stoker,
                              "from: 0.0\n  segments:\n    - {to: 0.25, width: 0.03}\n    - {to: "
                              "0.75, width: 0.016}\n    - {to: 1.0, width: 0.03}",
                              "edges: [0.0, 0.5, 0.5, 1.0]"));
  EXPECT_NE(message.find("zero or negative width"), std::string::npos) << message;
  EXPECT_NE(message.find("mesh.edges"), std::string::npos) << message;
  message =
      error_of(replaced(stoker, "width: 0.03}\n    - {to: 0.75", "width: -0.03}\n    - {to: 0.75"));
  EXPECT_NE(message.find("width"), std::string::npos) << message;
}

TEST(SweCase, RefusesAGaugeOutsideTheDomain) {
  const std::string message = error_of(replaced(stoker, "x: 0.5}", "x: 1.5}"));
  EXPECT_NE(message.find("gauge 'dam'"), std::string::npos) << message;
  EXPECT_NE(message.find("outside the domain"), std::string::npos) << message;
  EXPECT_NE(message.find("case.yaml:18"), std::string::npos) << message;
}

TEST(SweCase, RefusesABedProfileThatDoesNotCoverTheDomain) {
  const std::string text =
      replaced(stoker, "initial:", "bed: {profile: [[0.2, 0.0], [1.0, 0.1]]}\ninitial:");
  const std::string message = error_of(text);
  EXPECT_NE(message.find("bed.profile"), std::string::npos) << message;
  EXPECT_NE(message.find("must cover the domain"), std::string::npos) << message;
}

TEST(SweCase, RefusesKeysOfTheOtherDimension) {
  std::string message = error_of(
      replaced(stoker, "boundaries: {left: transmissive", "boundaries: {x_min: transmissive"));
  EXPECT_NE(message.find("not a face of a 1D case"), std::string::npos) << message;
  message = error_of(replaced(stoker, "x: 0.5}", "position: [0.5, 0.0]}"));
  EXPECT_NE(message.find("a 1D gauge takes `x`"), std::string::npos) << message;
}

TEST(SweCase, ReadsTheBedPressureModel) {
  EXPECT_EQ(swe::load_case_text(stoker, "c.yaml").coupling.pressure, swe::BedPressure::hydrostatic);
  const auto c = swe::load_case_text(stoker + "coupling: {bed_pressure: excess}\n", "c.yaml");
  EXPECT_EQ(c.coupling.pressure, swe::BedPressure::excess);
  const std::string message = error_of(stoker + "coupling: {bed_pressure: buoyant}\n");
  EXPECT_NE(message.find("coupling.bed_pressure"), std::string::npos) << message;
}

}  // namespace
