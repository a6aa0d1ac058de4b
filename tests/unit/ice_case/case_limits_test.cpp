// What an ICE case may ask for: its size is stated before the solver
// allocates anything and refused above limits.memory_gib (or beyond the
// solver's int indices), and its output intervals and standalone window must
// give a sane number of outputs and windows. Each refusal is located at the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"
#include "ice/case/load_case.hpp"
#include "input_error.hpp"
#include "replaced_text.hpp"

namespace ice {
namespace {

using cosim::testing::replaced;
using ::testing::HasSubstr;

const std::string tank = R"(kind: ice_case
name: tank
dimension: 3
grid: {origin: [0.0, 0.0, 0.0], upper: [1.0, 1.0, 1.0], cells: [10, 20, 30]}
gravity: [0.0, -9.81, 0.0]
end_time: 0.5
materials:
  water:
    eos: {type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8}
  air:
    eos: {type: ideal_gas, gas_constant: 287.0, heat_capacity_ratio: 1.4}
initial:
  fill: air
  regions:
    - {box: {lower: [0.0, 0.0, 0.0], upper: [1.0, 0.5, 1.0]}, fill: water}
output:
  every: 0.05
  gauge_every: 0.01
  gauges: [{name: g1, point: [0.5, 0.2, 0.5]}]
)";

std::string error_of(const std::string& text) {
  return cosim::testing::input_error_message([&] { load_case_text(text, "case.yaml"); });
}

TEST(IceCaseLimits, StatesItsCellsAndMemory) {
  const CaseDescription c = load_case_text(tank, "case.yaml");
  EXPECT_EQ(c.size.count("cells"), 6000.0);
  EXPECT_THAT(c.size.describe(), HasSubstr("6 000 cells, about "));
  // A second material costs memory in every cell.
  const CaseDescription water_only =
      load_case_text(replaced(replaced(tank,
                                       "  air:\n    eos: {type: ideal_gas, gas_constant: 287.0, "
                                       "heat_capacity_ratio: 1.4}\n",
                                       ""),
                              "fill: air", "fill: water"),
                     "case.yaml");
  EXPECT_LT(water_only.size.memory_bytes(), c.size.memory_bytes());
}

TEST(IceCaseLimits, TooManyCellsAreRefusedWithTheEstimate) {
  const std::string e =
      error_of(replaced(tank, "cells: [10, 20, 30]", "cells: [1000, 1000, 1000]"));
  EXPECT_THAT(e, HasSubstr("case.yaml:1:1: key 'limits.memory_gib': the run would need about"));
  EXPECT_THAT(e, HasSubstr("(1 000 000 000 cells)"));
  EXPECT_THAT(error_of(replaced(tank, "cells: [10, 20, 30]",
                                "cells: [10, 20, 30]}\nlimits: {memory_gib: 0.001")),
              HasSubstr("case.yaml:5:22: key 'limits.memory_gib'"));
}

TEST(IceCaseLimits, CellsOrFacesBeyondIntIndicesAreRefusedWhateverTheLimit) {
  const std::string huge = replaced(tank, "cells: [10, 20, 30]", "cells: [2000, 2000, 1000]") +
                           "limits: {memory_gib: 1.0e+9}\n";
  EXPECT_THAT(error_of(huge),
              HasSubstr("key 'grid.cells': the grid has 4 002 000 000 faces normal to x"));
}

TEST(IceCaseLimits, OutputIntervalsGivingMoreThanAMillionOutputsAreRefused) {
  EXPECT_THAT(error_of(replaced(tank, "every: 0.05", "every: 1.0e-300")),
              HasSubstr("case.yaml:17:10: key 'output.every'"));
  EXPECT_THAT(error_of(replaced(tank, "gauge_every: 0.01", "gauge_every: 1.0e-8")),
              HasSubstr("key 'output.gauge_every'"));
}

TEST(IceCaseLimits, AWindowGivingMoreThanAMillionWindowsIsRefused) {
  EXPECT_THAT(error_of(replaced(tank, "end_time: 0.5", "end_time: 0.5\nwindow: 1.0e-9")),
              HasSubstr("case.yaml:7:9: key 'window': the window 1e-09 s gives 5e+08 windows"));
  EXPECT_NO_THROW(
      load_case_text(replaced(tank, "end_time: 0.5", "end_time: 0.5\nwindow: 0.01"), "case.yaml"));
}

}  // namespace
}  // namespace ice
