// What an OpenFOAM case may ask for: its cells (the generated grid's, or a
// user case's as its mesh or blockMeshDict states them) and memory are
// stated and refused above limits.memory_gib, and its snapshot interval and
// window must give a sane number of outputs and starts. Each refusal is
// located at the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cosim/error.hpp"
#include "input_error.hpp"
#include "openfoam/case/load_case.hpp"
#include "openfoam/case/mesh_cell_count.hpp"
#include "replaced_text.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace openfoam {
namespace {

namespace fs = std::filesystem;
using cosim::testing::replaced;
using cosim::testing::write_text;
using ::testing::HasSubstr;

const std::string tank = R"(kind: openfoam_case
name: tank
generate:
  dimension: 2
  grid: {origin: [0.0, 0.0], upper: [0.4, 0.2], cells: [80, 40]}
  fluids:
    water: {density: 1000, viscosity: 1.0e-3}
    air: {density: 1, viscosity: 1.8e-5}
end_time: 0.3
time_step: 1.0e-3
window: 0.01
output: {every: 0.05}
)";

std::string error_of(const std::string& text) {
  return cosim::testing::input_error_message([&] { load_case_text(text, "case.yaml"); });
}

TEST(OpenFoamCaseLimits, AGeneratedCaseStatesItsCellsAndMemory) {
  const CaseDescription c = load_case_text(tank, "case.yaml");
  EXPECT_EQ(c.size.count("cells"), 3200.0);
  EXPECT_THAT(c.size.describe(), HasSubstr("3 200 cells, about "));
  // Each OpenFOAM process costs its own memory.
  const CaseDescription parallel =
      load_case_text(tank + "parallel: {processes: 4, split: [2, 2, 1]}\n", "case.yaml");
  EXPECT_GT(parallel.size.memory_bytes(), c.size.memory_bytes());
}

TEST(OpenFoamCaseLimits, TooManyCellsAreRefusedWithTheEstimate) {
  const std::string e = error_of(replaced(tank, "cells: [80, 40]", "cells: [50000, 20000]"));
  EXPECT_THAT(e, HasSubstr("case.yaml:1:1: key 'limits.memory_gib': the run would need about"));
  EXPECT_THAT(e, HasSubstr("(1 000 000 000 cells)"));
  // Beyond OpenFOAM's 32-bit labels whatever the limit.
  EXPECT_THAT(error_of(replaced(tank, "cells: [80, 40]", "cells: [200000, 100000]")),
              HasSubstr("key 'generate.grid.cells': the case makes 20 000 000 000 cells, more than "
                        "the solver's indices hold"));
  EXPECT_THAT(error_of(tank + "limits: {memory_gib: 0.01}\n"),
              HasSubstr("case.yaml:13:22: key 'limits.memory_gib'"));
}

TEST(OpenFoamCaseLimits, AUsersCaseIsCountedFromItsMeshOrItsBlocks) {
  cosim::testing::ScratchDirectory scratch;
  // blockMeshDict: two blocks, one with a zone name, comments dropped.
  write_text(scratch / "blocks" / "system" / "blockMeshDict", R"(FoamFile { version 2.0; }
// blocks ( hex (0 1 2 3 4 5 6 7) (1000 1 1) )
blocks
(
    hex (0 1 2 3 4 5 6 7) (160 2 1) simpleGrading (1 1 1)
    /* a second block */
    hex (1 8 9 2 5 10 11 6) porous (40 2 1) simpleGrading (1 ((0.5 0.5 2) (0.5 0.5 0.5)) 1)
);
)");
  EXPECT_EQ(mesh_cell_count(scratch / "blocks"), 400.0);
  // A mesh made already: its owner file's header.
  write_text(scratch / "mesh" / "constant" / "polyMesh" / "owner",
             "FoamFile\n{\n    note        \"nPoints:1234  nCells:5678  nFaces:999  "
             "nInternalFaces:99\";\n}\n");
  EXPECT_EQ(mesh_cell_count(scratch / "mesh"), 5678.0);
  // Macros in the counts: unknown, not guessed.
  write_text(scratch / "macros" / "system" / "blockMeshDict",
             "n 10;\nblocks ( hex (0 1 2 3 4 5 6 7) ($n 1 1) simpleGrading (1 1 1) );\n");
  EXPECT_EQ(mesh_cell_count(scratch / "macros"), std::nullopt);
  EXPECT_EQ(mesh_cell_count(scratch / "nothing"), std::nullopt);

  const fs::path shipped = fs::path(COSIM_SOURCE_DIR) / "configs" / "openfoam_coupled" /
                           "darcy_user_case" / "water.yaml";
  EXPECT_EQ(load_case(shipped).size.count("cells"), 160.0);
}

// Before: an interval of 1e-300 s was accepted (and a whole number of
// steps only for steps as small).
TEST(OpenFoamCaseLimits, SnapshotIntervalsAndWindowsGivingMoreThanAMillionAreRefused) {
  const std::string tiny_steps = replaced(tank, "time_step: 1.0e-3", "time_step: 1.0e-12");
  EXPECT_THAT(error_of(replaced(tiny_steps, "output: {every: 0.05}", "output: {every: 1.0e-12}")),
              HasSubstr("case.yaml:12:17: key 'output.every': an interval of 1e-12 s gives"));
  EXPECT_THAT(error_of(replaced(tiny_steps, "window: 0.01", "window: 1.0e-10")),
              HasSubstr("key 'window': the window 1e-10 s starts OpenFOAM 3e+09 times"));
}

}  // namespace
}  // namespace openfoam
