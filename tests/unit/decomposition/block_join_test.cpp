// Arrays of the blocks of one decomposition joined into the blocks of
// another (a checkpoint restarted on another count of ranks): every value
// inside the grid comes from the block that owns its cell (the ghosts of
// the blocks written hold garbage here), every ghost beyond the grid's edge
// from a block that stores it.
#include "cosim/decomposition/block_join.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace cosim::decomposition {
namespace {

using Index = std::array<std::int64_t, 3>;

// A value for every cell of the grid and of its surroundings.
double value_at(const Index& cell) {
  return static_cast<double>(cell[0]) + 100.0 * static_cast<double>(cell[1]) +
         1e4 * static_cast<double>(cell[2]);
}

// The blocks of `cells` split dims[d] ways, each with its array: the value of
// every owned cell and of every ghost beyond the grid, garbage elsewhere.
struct Written {
  std::vector<StoredBlock> blocks;
  std::vector<std::vector<double>> arrays;
};

Written write(const Index& cells, std::array<int, 3> dims, std::array<int, 3> ghosts) {
  const int dim = cells[2] > 1 ? 3 : 2;
  const CartesianDecomposition decomposition(dim, cells, dims);
  Written w;
  for (int r = 0; r < decomposition.ranks(); ++r) {
    const StoredBlock b = StoredBlock::padded(decomposition.block(r).cells, ghosts);
    std::vector<double> array;
    for (std::int64_t k = b.stored[2].begin; k < b.stored[2].end; ++k)
      for (std::int64_t j = b.stored[1].begin; j < b.stored[1].end; ++j)
        for (std::int64_t i = b.stored[0].begin; i < b.stored[0].end; ++i) {
          const Index cell{i, j, k};
          bool owned = true, beyond = false;
          for (std::size_t d = 0; d < 3; ++d) {
            owned = owned && cell[d] >= b.owned[d].begin && cell[d] < b.owned[d].end;
            beyond = beyond || cell[d] < 0 || cell[d] >= cells[d];
          }
          array.push_back(owned || beyond ? value_at(cell)
                                          : std::numeric_limits<double>::quiet_NaN());
        }
    EXPECT_EQ(array.size(), b.size());
    w.blocks.push_back(b);
    w.arrays.push_back(std::move(array));
  }
  return w;
}

void expect_joined(const Index& cells, std::array<int, 3> written_dims,
                   std::array<int, 3> read_dims, std::array<int, 3> ghosts) {
  const Written w = write(cells, written_dims, ghosts);
  std::vector<std::span<const double>> values(w.arrays.begin(), w.arrays.end());
  const int dim = cells[2] > 1 ? 3 : 2;
  const CartesianDecomposition reading(dim, cells, read_dims);
  for (int r = 0; r < reading.ranks(); ++r) {
    const StoredBlock to = StoredBlock::padded(reading.block(r).cells, ghosts);
    std::vector<double> joined(to.size(), -1.0);
    EXPECT_EQ(join_blocks(w.blocks, values, cells, to, joined), 0u);
    std::size_t n = 0;
    for (std::int64_t k = to.stored[2].begin; k < to.stored[2].end; ++k)
      for (std::int64_t j = to.stored[1].begin; j < to.stored[1].end; ++j)
        for (std::int64_t i = to.stored[0].begin; i < to.stored[0].end; ++i, ++n)
          ASSERT_EQ(joined[n], value_at({i, j, k}))
              << "block " << r << " cell " << i << ", " << j << ", " << k;
  }
}

TEST(BlockJoin, TwoBlocksIntoOneThreeAndTheOtherDirection) {
  const Index cells{7, 5, 1};
  const std::array<int, 3> ghosts{2, 2, 0};
  expect_joined(cells, {2, 1, 1}, {1, 1, 1}, ghosts);
  expect_joined(cells, {2, 1, 1}, {3, 1, 1}, ghosts);
  expect_joined(cells, {2, 1, 1}, {1, 2, 1}, ghosts);
  expect_joined(cells, {1, 1, 1}, {2, 2, 1}, ghosts);
}

TEST(BlockJoin, ThreeDimensionalBlocksWithWideGhosts) {
  expect_joined({6, 5, 4}, {2, 1, 2}, {1, 3, 1}, {3, 3, 3});
}

// Two values per cell, blocks widened toward their neighbours alone (as
// ICE's), and faces: a face array along x is a cell array one longer along
// x, whose blocks own their upper face too (shared with the next block).
TEST(BlockJoin, ComponentsAndBlocksWidenedTowardTheirNeighbours) {
  const Index faces{8, 3, 1};  // the x faces of a grid of 7 x 3 cells
  std::vector<StoredBlock> blocks;
  std::vector<std::vector<double>> arrays;
  for (const auto& [owned, stored] :
       {std::pair{Range{0, 4}, Range{0, 6}}, std::pair{Range{3, 8}, Range{1, 8}}}) {
    StoredBlock b{{owned, Range{0, 3}, Range{0, 1}}, {stored, Range{0, 3}, Range{0, 1}}, 2};
    std::vector<double> array;
    for (std::int64_t j = 0; j < 3; ++j)
      for (std::int64_t i = stored.begin; i < stored.end; ++i)
        for (int k = 0; k < 2; ++k) array.push_back(value_at({i, j, 0}) + 0.5 * k);
    blocks.push_back(b);
    arrays.push_back(std::move(array));
  }
  std::vector<std::span<const double>> values(arrays.begin(), arrays.end());
  StoredBlock whole{
      {Range{0, 8}, Range{0, 3}, Range{0, 1}}, {Range{0, 8}, Range{0, 3}, Range{0, 1}}, 2};
  std::vector<double> joined(whole.size(), -1.0);
  EXPECT_EQ(join_blocks(blocks, values, faces, whole, joined), 0u);
  for (std::int64_t j = 0; j < 3; ++j)
    for (std::int64_t i = 0; i < 8; ++i)
      for (int k = 0; k < 2; ++k)
        EXPECT_EQ(joined[static_cast<std::size_t>((j * 8 + i) * 2 + k)],
                  value_at({i, j, 0}) + 0.5 * k);
}

TEST(BlockJoin, CountsWhatNoBlockHolds) {
  const Written w = write({7, 5, 1}, {2, 1, 1}, {0, 0, 0});
  std::vector<std::span<const double>> values(w.arrays.begin(), w.arrays.end());
  // Ghosts beyond the grid that the blocks written did not store.
  const StoredBlock to = StoredBlock::padded({Range{0, 7}, Range{0, 5}, Range{0, 1}}, {1, 1, 0});
  std::vector<double> joined(to.size(), -1.0);
  EXPECT_EQ(join_blocks(w.blocks, values, {7, 5, 1}, to, joined), 9u * 7u - 7u * 5u);
}

}  // namespace
}  // namespace cosim::decomposition
