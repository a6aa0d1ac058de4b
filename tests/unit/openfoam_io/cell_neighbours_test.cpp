#include "openfoam/io/cell_neighbours.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "scratch_directory.hpp"

namespace openfoam {
namespace {

namespace fs = std::filesystem;

std::vector<std::size_t> sorted(std::span<const std::size_t> cells) {
  std::vector<std::size_t> v(cells.begin(), cells.end());
  std::sort(v.begin(), v.end());
  return v;
}

void write_labels(const fs::path& file, const std::string& object, const std::vector<int>& labels) {
  std::ofstream out(file);
  out << "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class labelList;\n"
      << "    note \"nCells:4\";\n    location \"constant/polyMesh\";\n    object " << object
      << ";\n}\n\n"
      << labels.size() << "\n(\n";
  for (int l : labels) out << l << "\n";
  out << ")\n";
}

TEST(OpenFoamCellNeighbours, AGridsCellsShareFacesAlongEachDirection) {
  const CellNeighbours n = CellNeighbours::of_grid({3, 2, 1});
  ASSERT_EQ(n.size(), 6u);
  // Cell 1 (i = 1, j = 0): x neighbours 0 and 2, y neighbour 4, lower first.
  EXPECT_EQ(std::vector<std::size_t>(n.of(1).begin(), n.of(1).end()),
            (std::vector<std::size_t>{0, 2, 4}));
  EXPECT_EQ(sorted(n.of(5)), (std::vector<std::size_t>{2, 4}));
}

// Four cells in a 2 x 2 square, as a mesh numbers its faces: 4 internal
// faces (owner < neighbour), then 8 boundary faces owned by the cells.
TEST(OpenFoamCellNeighbours, AMeshsInternalFacesJoinTheirOwnerAndNeighbour) {
  cosim::testing::ScratchDirectory dir;
  write_labels(dir / "owner", "owner", {0, 0, 1, 2, 0, 0, 1, 1, 2, 2, 3, 3});
  write_labels(dir / "neighbour", "neighbour", {1, 2, 3, 3});
  const CellNeighbours n = CellNeighbours::of_mesh(dir.path(), 4);
  ASSERT_EQ(n.size(), 4u);
  EXPECT_EQ(sorted(n.of(0)), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(sorted(n.of(3)), (std::vector<std::size_t>{1, 2}));
  // The grid of the same square gives the same neighbours.
  const CellNeighbours grid = CellNeighbours::of_grid({2, 2, 1});
  for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(sorted(n.of(c)), sorted(grid.of(c)));
}

TEST(OpenFoamCellNeighbours, ALabelOutsideTheMeshIsNamed) {
  cosim::testing::ScratchDirectory dir;
  write_labels(dir / "owner", "owner", {0, 0, 1, 2});
  write_labels(dir / "neighbour", "neighbour", {1, 2, 3, 7});
  try {
    (void)CellNeighbours::of_mesh(dir.path(), 4);
    FAIL() << "no error";
  } catch (const cosim::Error& e) {
    EXPECT_EQ(e.code(), cosim::ExitCode::participant_failed);
    EXPECT_NE(std::string(e.what()).find("neighbour"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("7"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace openfoam
