// OpenFOAM on several processes: the split of the simple method chosen from
// the mesh, and the job's `ranks` of the adapter's participant as the
// case's process count.
#include "openfoam/case/decomposition.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "input_error.hpp"
#include "openfoam/case/load_case.hpp"

namespace openfoam {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// Cell centres (x, y, z) of a uniform grid of nx x ny x nz unit cells.
std::vector<double> grid_centres(int nx, int ny, int nz) {
  std::vector<double> centres;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) centres.insert(centres.end(), {i + 0.5, j + 0.5, k + 0.5});
  return centres;
}

TEST(OpenFoamSplit, CutsTheFewestFacesAndGivesEveryBlockALayer) {
  // A channel of one row: all along x.
  EXPECT_THAT(choose_split(4, grid_centres(160, 1, 1)), ElementsAre(4, 1, 1));
  // A square: 2 x 2 cuts 2 x 40 faces, 4 x 1 cuts 3 x 40.
  EXPECT_THAT(choose_split(4, grid_centres(40, 40, 1)), ElementsAre(2, 2, 1));
  // A tall tank: across its height first.
  EXPECT_THAT(choose_split(2, grid_centres(10, 80, 1)), ElementsAre(1, 2, 1));
  // A tie goes to x.
  EXPECT_THAT(choose_split(2, grid_centres(20, 20, 1)), ElementsAre(2, 1, 1));
  // 3D: 8 processes on a cube are 2 x 2 x 2.
  EXPECT_THAT(choose_split(8, grid_centres(12, 12, 12)), ElementsAre(2, 2, 2));
  // A prime count on a square goes along one direction.
  EXPECT_THAT(choose_split(3, grid_centres(30, 30, 1)), ElementsAre(3, 1, 1));
  EXPECT_THAT(choose_split(1, grid_centres(5, 5, 1)), ElementsAre(1, 1, 1));
}

TEST(OpenFoamSplit, MoreProcessesThanLayersAreRefused) {
  try {
    choose_split(5, grid_centres(4, 1, 1));
    FAIL() << "5 blocks of 4 cells were not refused";
  } catch (const cosim::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot run on 5 processes"));
    EXPECT_THAT(e.what(), HasSubstr("4 x 1 x 1 layers"));
  }
}

const std::string channel = R"(kind: openfoam_case
name: channel
generate:
  dimension: 2
  grid: {origin: [0.0, 0.0], upper: [2.0, 0.1], cells: [160, 1]}
  gravity: [0, 0]
  fluids:
    water: {density: 998.0, viscosity: 1.0e-3}
    air: {density: 1.0, viscosity: 1.8e-5}
end_time: 0.01
time_step: 1.0e-4
)";

TEST(OpenFoamSplit, TheJobsRanksAreTheCasesProcesses) {
  const CaseDescription serial = load_case_text(channel, "case.yaml");
  EXPECT_EQ(serial.processes, 1);
  const CaseDescription four = load_case_text(channel, "case.yaml", 4);
  EXPECT_EQ(four.processes, 4);
  EXPECT_FALSE(four.split_given);
  // Each OpenFOAM process costs its own memory.
  EXPECT_GT(four.size.memory_bytes(), serial.size.memory_bytes());
  // The case may say the same count, with its own split.
  const CaseDescription same =
      load_case_text(channel + "parallel: {processes: 4, split: [4, 1, 1]}\n", "case.yaml", 4);
  EXPECT_EQ(same.processes, 4);
  EXPECT_TRUE(same.split_given);
  // Another count is refused at the case's key.
  const std::string e = cosim::testing::input_error_message(
      [&] { load_case_text(channel + "parallel: {processes: 2}\n", "case.yaml", 4); });
  EXPECT_THAT(e, HasSubstr("case.yaml:12:"));
  EXPECT_THAT(e, HasSubstr("parallel.processes"));
  EXPECT_THAT(e, HasSubstr("on 4 processes (its `ranks`), the case on 2"));
}

}  // namespace
}  // namespace openfoam
