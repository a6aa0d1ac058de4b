// What an MPM case may ask for: its particles (estimated from each body's
// region before it is seeded, 2D and 3D) and grid are stated and refused
// above limits.memory_gib or beyond what the solver's counters hold, and its
// output intervals must give a sane number of outputs. Each refusal is
// located at the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"
#include "input_error.hpp"
#include "mpm/case/load_case.hpp"
#include "replaced_text.hpp"

namespace mpm {
namespace {

using cosim::testing::replaced;
using ::testing::HasSubstr;

// A 20 x 20 grid (h = 0.05 m), a block of 4 x 4 cells and a floor of 20 x 2
// cells, 2 x 2 particles per cell.
const std::string drop = R"(kind: mpm_case
name: drop
dimension: 2
grid: {origin: [0, 0], upper: [1, 1], cells: [20, 20]}
time: {end_time: 0.1}
materials:
  rubber: {type: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
bodies:
  - name: block
    material: rubber
    geometry: {box: {min: [0.4, 0.5], max: [0.6, 0.7]}}
    particles_per_cell: 2
  - name: floor
    rigid: {motion: fixed}
    density: 2000
    geometry: {box: {min: [0, 0], max: [1, 0.1]}}
probes:
  - {name: centre, body: block, position: [0.5, 0.6]}
output: {every: 0.01, probe_every: 0.001}
)";

// A 3D cube of soil, 10 cells a side, in a grid of 20^3 cells.
const std::string cube = R"(kind: mpm_case
name: cube
dimension: 3
grid: {origin: [0, 0, 0], upper: [1, 1, 1], cells: [20, 20, 20]}
time: {end_time: 0.1}
materials:
  sand: {type: linear_elastic, density: 2000, youngs_modulus: 1.0e7, poisson_ratio: 0.3}
bodies:
  - name: cube
    material: sand
    geometry: {box: {min: [0.25, 0.25, 0.25], max: [0.75, 0.75, 0.75]}}
    particles_per_cell: 2
)";

std::string error_of(const std::string& text) {
  return cosim::testing::input_error_message([&] { load_case_text(text, "case.yaml"); });
}

TEST(MpmCaseLimits, StatesTheParticlesSeededAndTheGrid) {
  const CaseDescription c = load_case_text(drop, "case.yaml");
  EXPECT_EQ(c.size.count("particles"), 16 * 4 + 40 * 4);
  EXPECT_EQ(c.size.count("grid nodes"), 21 * 21);
  EXPECT_THAT(c.size.describe(), HasSubstr("224 particles, 441 grid nodes, about "));
  const CaseDescription c3 = load_case_text(cube, "case.yaml");
  EXPECT_EQ(c3.size.count("particles"), 1000 * 8);
  EXPECT_EQ(c3.size.count("grid nodes"), 21 * 21 * 21);
  EXPECT_GT(c3.size.memory_bytes(), c.size.memory_bytes());
}

// Before: 10^10 particles per cell were seeded until memory ran out.
TEST(MpmCaseLimits, AHundredThousandParticlesPerCellAreRefusedBeforeSeeding) {
  // Beyond the particles' 32-bit indices, whatever the limit.
  const std::string e =
      error_of(replaced(drop, "particles_per_cell: 2", "particles_per_cell: 100000"));
  EXPECT_THAT(e, HasSubstr("case.yaml:9:3: key 'bodies': the case makes 160 000 000 000 particles, "
                           "more than the solver's indices hold (4 294 967 295)"));
  EXPECT_THAT(e, HasSubstr("the run would need about"));
  EXPECT_THAT(e, HasSubstr("(160 000 000 000 particles, 441 grid nodes)"));
  // Within the indices, above the memory limit.
  const std::string m =
      error_of(replaced(drop, "particles_per_cell: 2", "particles_per_cell: 1000"));
  EXPECT_THAT(m, HasSubstr("case.yaml:1:1: key 'limits.memory_gib': the run would need about"));
  EXPECT_THAT(m, HasSubstr("(16 000 000 particles, 441 grid nodes)"));
  EXPECT_THAT(m, HasSubstr("raise limits.memory_gib"));
}

TEST(MpmCaseLimits, A3DBodyIsEstimatedFromItsVolume) {
  // 1000 cells of 10^6 particles each.
  const std::string e =
      error_of(replaced(cube, "particles_per_cell: 2", "particles_per_cell: 100"));
  EXPECT_THAT(e, HasSubstr("(1 000 000 000 particles, 9 261 grid nodes)"));
  // A grid of 10^12 nodes is refused before any body is looked at.
  EXPECT_THAT(error_of(replaced(cube, "cells: [20, 20, 20]", "cells: [10000, 10000, 10000]")),
              HasSubstr("(0 particles, 1 000 300 030 001 grid nodes)"));
}

TEST(MpmCaseLimits, TheLimitIsTheCasesToLowerOrRaise) {
  const std::string lowered = drop + "limits: {memory_gib: 0.001}\n";
  EXPECT_THAT(error_of(lowered), HasSubstr("case.yaml:20:22: key 'limits.memory_gib'"));
  EXPECT_THAT(error_of(lowered), HasSubstr("more than the limit of 0.001 GiB"));
  EXPECT_EQ(error_of(drop + "limits: {memory_gib: 1}\n"), "no error");
}

TEST(MpmCaseLimits, ParticlesPerCellBeyondTheSeedingsCountersAreRefused) {
  // A sliver of a cell: few particles, but 2.5e9 points per cell to place.
  const std::string sliver = replaced(drop, "{box: {min: [0.4, 0.5], max: [0.6, 0.7]}}",
                                      "{box: {min: [0.4, 0.5], max: [0.401, 0.501]}}");
  EXPECT_THAT(
      error_of(replaced(sliver, "particles_per_cell: 2", "particles_per_cell: 50000")),
      HasSubstr("key 'bodies[0].particles_per_cell': 2 500 000 000 particles per cell, more "
                "than the seeding's counters hold (2 147 483 647)"));
  const std::string fine_grid = replaced(sliver, "cells: [20, 20]", "cells: [1000000, 1]");
  EXPECT_THAT(
      error_of(replaced(fine_grid, "particles_per_cell: 2", "particles_per_cell: [3000, 1]")),
      HasSubstr("3000 particles per cell along 1000000 grid cells"));
}

// Before: an interval of 1e-300 s made the run spin forever in its first step.
TEST(MpmCaseLimits, OutputIntervalsGivingMoreThanAMillionOutputsAreRefused) {
  EXPECT_THAT(error_of(replaced(drop, "every: 0.01", "every: 1.0e-300")),
              HasSubstr("case.yaml:19:17: key 'output.every': an interval of 1e-300 s gives"));
  EXPECT_THAT(error_of(replaced(drop, "probe_every: 0.001", "probe_every: 1.0e-8")),
              HasSubstr("key 'output.probe_every'"));
}

}  // namespace
}  // namespace mpm
