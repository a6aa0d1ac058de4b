#include "cosim/decomposition/cartesian_decomposition.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cosim/error.hpp"

namespace cosim::decomposition {
namespace {

TEST(EvenRange, CoversTheCellsWithPartsDifferingByOneAtMost) {
  for (const std::int64_t count : {1, 7, 10, 101})
    for (int parts = 1; parts <= std::min<std::int64_t>(count, 9); ++parts) {
      std::int64_t next = 0, shortest = count, longest = 0;
      for (int p = 0; p < parts; ++p) {
        const Range r = even_range(count, parts, p);
        EXPECT_EQ(r.begin, next);
        next = r.end;
        shortest = std::min(shortest, r.size());
        longest = std::max(longest, r.size());
      }
      EXPECT_EQ(next, count);
      EXPECT_LE(longest - shortest, 1);
    }
}

TEST(ProcessGrid, CutsWhereTheFacesAreSmallest) {
  const std::vector<std::int64_t> square{100, 100}, strip{1000, 4}, oblong{30, 20},
      cube{64, 64, 64}, line{50};
  EXPECT_EQ(process_grid(4, square), (std::array<int, 3>{2, 2, 1}));
  EXPECT_EQ(process_grid(4, strip), (std::array<int, 3>{4, 1, 1}));  // MPI_Dims_create: 2 x 2
  EXPECT_EQ(process_grid(6, oblong), (std::array<int, 3>{3, 2, 1}));
  EXPECT_EQ(process_grid(8, cube), (std::array<int, 3>{2, 2, 2}));
  EXPECT_EQ(process_grid(7, line), (std::array<int, 3>{7, 1, 1}));
  EXPECT_EQ(process_grid(1, cube), (std::array<int, 3>{1, 1, 1}));
}

TEST(ProcessGrid, RefusesMoreRanksThanCells) {
  const std::vector<std::int64_t> tiny{3, 1};
  try {
    (void)process_grid(5, tiny);
    FAIL() << "5 ranks on 3 x 1 cells";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("5 ranks do not fit a grid of 3 x 1 cells"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW((void)process_grid(0, tiny), InputError);
}

TEST(CartesianDecomposition, BlocksPartitionTheGridAndKnowTheirNeighbours) {
  const CartesianDecomposition grid(3, {10, 7, 5}, {3, 2, 2});
  ASSERT_EQ(grid.ranks(), 12);
  std::vector<int> owners(10 * 7 * 5, -1);
  for (int rank = 0; rank < grid.ranks(); ++rank) {
    EXPECT_EQ(grid.rank_of(grid.coords_of(rank)), rank);
    const Block b = grid.block(rank);
    for (auto k = b.cells[2].begin; k < b.cells[2].end; ++k)
      for (auto j = b.cells[1].begin; j < b.cells[1].end; ++j)
        for (auto i = b.cells[0].begin; i < b.cells[0].end; ++i) {
          int& owner = owners[static_cast<std::size_t>((k * 7 + j) * 10 + i)];
          EXPECT_EQ(owner, -1) << "a cell owned twice";
          owner = rank;
          EXPECT_EQ(grid.owner({i, j, k}), rank);
        }
    for (std::size_t face = 0; face < 6; ++face) {
      const int other = b.neighbour[face];
      if (other < 0) continue;
      EXPECT_EQ(grid.block(other).neighbour[face ^ 1u], rank);  // the face across points back
    }
  }
  for (int owner : owners) EXPECT_GE(owner, 0);
  // MPI_Cart_create's order: the last direction fastest.
  EXPECT_EQ(grid.coords_of(1), (std::array<int, 3>{0, 0, 1}));
  EXPECT_EQ(grid.coords_of(2), (std::array<int, 3>{0, 1, 0}));
  EXPECT_EQ(grid.block(0).neighbour[0], -1);
  EXPECT_EQ(grid.block(0).neighbour[1], grid.rank_of({1, 0, 0}));
}

TEST(CartesianDecomposition, RefusesPartsWithoutCells) {
  EXPECT_THROW(CartesianDecomposition(2, {4, 3, 1}, {5, 1, 1}), InputError);
  EXPECT_THROW(CartesianDecomposition(2, {4, 3, 1}, {1, 1, 2}), InputError);
  EXPECT_THROW(CartesianDecomposition(4, {4, 3, 1}, {1, 1, 1}), InputError);
  const CartesianDecomposition line(1, {9, 0, 0}, {3, 1, 1});
  EXPECT_EQ(line.block(2).cells[0].begin, 6);
  EXPECT_THROW((void)line.block(3), InputError);
  EXPECT_THROW((void)line.owner({9, 0, 0}), InputError);
}

}  // namespace
}  // namespace cosim::decomposition
