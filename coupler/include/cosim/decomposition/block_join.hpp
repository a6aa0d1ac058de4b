#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "cosim/decomposition/cartesian_decomposition.hpp"

// The arrays of a block of a structured grid, written by the ranks of one
// decomposition, read into the blocks of another (issue 27: a checkpoint
// restarted on another count of ranks). Pure arithmetic.
namespace cosim::decomposition {

// Where one block's array lies in the whole grid: the cells it owns, and
// the cells it stores (the owned ones and ghost layers around them), x
// fastest, then y, then z; beyond the grid's dimension both are {0, 1}.
// `components` values per cell, one after the other.
struct StoredBlock {
  std::array<Range, 3> owned{};
  std::array<Range, 3> stored{};
  int components = 1;

  // The owned cells with `ghosts` layers on both sides of each direction.
  static StoredBlock padded(const std::array<Range, 3>& owned, std::array<int, 3> ghosts,
                            int components = 1);
  // The stored values.
  std::size_t size() const;
};

// Fills `to`'s array `values_to` (to.size() values) from the arrays `values`
// of the blocks `from` (of another decomposition of the same grid of
// grid_cells cells, with as many components): a value inside the grid from
// the block that owns its cell, one of a ghost beyond the grid's edge from a
// block that stores it. Returns the count of cells no block had (left as
// they were).
std::size_t join_blocks(std::span<const StoredBlock> from,
                        std::span<const std::span<const double>> values,
                        const std::array<std::int64_t, 3>& grid_cells, const StoredBlock& to,
                        std::span<double> values_to);

}  // namespace cosim::decomposition
