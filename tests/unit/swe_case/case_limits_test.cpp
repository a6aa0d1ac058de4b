// What a shallow-water case may ask for: its size is stated before anything
// is allocated and refused above limits.memory_gib, and its output
// intervals and standalone window must give a sane number of outputs and
// windows. Each refusal is located at the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"
#include "input_error.hpp"
#include "replaced_text.hpp"
#include "swe/case/load_case.hpp"

namespace {

using cosim::testing::replaced;
using ::testing::HasSubstr;

const std::string dam = R"(kind: swe_case
name: dam
dimension: 1
mesh:
  from: 0.0
  segments:
    - {to: 0.5, width: 0.01}
    - {to: 1.0, width: 0.02}
initial:
  depth: 0.5
  regions:
    - {box: {min: [0.0], max: [0.5]}, depth: 1.0}
time: {end_time: 0.1}
output:
  every: 0.01
  gauge_every: 0.001
  gauges:
    - {name: dam, x: 0.5}
)";

const std::string basin = R"(kind: swe_case
name: basin
dimension: 2
mesh: {origin: [0.0, 0.0], upper: [10.0, 10.0], cells: [100, 100]}
initial: {free_surface: 1.0}
time: {end_time: 1.0}
)";

std::string error_of(const std::string& text) {
  return cosim::testing::input_error_message([&] { swe::load_case_text(text, "case.yaml"); });
}

TEST(SweCaseLimits, StatesItsCellsAndMemory) {
  const swe::CaseDescription c = swe::load_case_text(dam, "case.yaml");
  EXPECT_EQ(c.size.count("cells"), 75.0);
  EXPECT_GT(c.size.memory_bytes(), 0.0);
  EXPECT_THAT(c.size.describe(), HasSubstr("75 cells, about "));
  EXPECT_EQ(swe::load_case_text(basin, "case.yaml").size.count("cells"), 10000.0);
}

// Before: the loader made a trillion edges, one at a time, until memory ran out.
TEST(SweCaseLimits, ACellWidthOfAPicometreIsRefusedBeforeAnyEdgeIsMade) {
  const std::string e = error_of(replaced(dam, "width: 0.01}", "width: 1.0e-12}"));
  EXPECT_THAT(e, HasSubstr("case.yaml:1:1: key 'limits.memory_gib'"));
  EXPECT_THAT(e, HasSubstr("(500 000 000 025 cells)"));
  EXPECT_THAT(e, HasSubstr("raise limits.memory_gib"));
}

TEST(SweCaseLimits, TooManyCellsAreRefusedIn1DAnd2D) {
  EXPECT_THAT(error_of(replaced(
                  dam, "segments:\n    - {to: 0.5, width: 0.01}\n    - {to: 1.0, width: 0.02}",
                  "to: 1.0\n  cells: 2000000000")),
              HasSubstr("(2 000 000 000 cells)"));
  EXPECT_THAT(error_of(replaced(basin, "cells: [100, 100]", "cells: [1000000, 1000000]")),
              HasSubstr("key 'limits.memory_gib': the run would need about"));
}

TEST(SweCaseLimits, TheLimitIsTheCasesToLowerOrRaise) {
  const std::string big = replaced(basin, "cells: [100, 100]", "cells: [2000, 2000]");
  EXPECT_EQ(error_of(big), "no error");
  const std::string lowered = big + "limits: {memory_gib: 0.05}\n";
  EXPECT_THAT(error_of(lowered), HasSubstr("case.yaml:7:22: key 'limits.memory_gib'"));
  EXPECT_THAT(error_of(lowered), HasSubstr("(4 000 000 cells), more than the limit of 0.05 GiB"));
  EXPECT_THAT(error_of(basin + "limits: {memory: 1}\n"), HasSubstr("memory"));
}

// Before: an interval of 1e-300 s made the run spin forever in its first step.
TEST(SweCaseLimits, OutputIntervalsGivingMoreThanAMillionOutputsAreRefused) {
  EXPECT_THAT(error_of(replaced(dam, "every: 0.01", "every: 1.0e-300")),
              HasSubstr("case.yaml:15:10: key 'output.every': an interval of 1e-300 s gives"));
  EXPECT_THAT(error_of(replaced(dam, "gauge_every: 0.001", "gauge_every: 1.0e-9")),
              HasSubstr("key 'output.gauge_every'"));
}

TEST(SweCaseLimits, AWindowGivingMoreThanAMillionWindowsIsRefused) {
  EXPECT_THAT(
      error_of(replaced(dam, "time: {end_time: 0.1}", "time: {end_time: 0.1, window: 1e-9}")),
      HasSubstr("case.yaml:13:31: key 'time.window': the window 1e-09 s gives 1e+08 windows"));
  EXPECT_NO_THROW(swe::load_case_text(
      replaced(dam, "time: {end_time: 0.1}", "time: {end_time: 0.1, window: 0.01}"), "case.yaml"));
}

}  // namespace
