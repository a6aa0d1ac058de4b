#pragma once

#include <array>
#include <cstdint>
#include <span>

// The decomposition of a structured grid over MPI ranks (issue 27): which
// cells each rank owns and who its neighbours are. Pure arithmetic, so that
// every solver splits its grid the same way and the coupler can tell, from
// the job alone, which parts of two participants overlap. Ranks are numbered
// as MPI_Cart_create numbers them (row-major, the last direction fastest).
namespace cosim::decomposition {

// Half-open [begin, end) of cells.
struct Range {
  std::int64_t begin = 0, end = 0;
  std::int64_t size() const { return end - begin; }
};

// Part `part` of `count` cells split into `parts` contiguous parts as evenly
// as possible: the first count % parts parts hold one cell more.
Range even_range(std::int64_t count, int parts, int part);

// The process grid for `ranks` ranks over a grid of cells[d] cells in each of
// its cells.size() (1 to 3) directions: the factorisation of `ranks` (one
// factor per direction, none larger than that direction's cells) whose
// faces between parts cross the fewest cells, i.e. the least halo to
// exchange each step. MPI_Dims_create ignores the grid's shape (it would cut
// a 1000 x 4 strip over 4 ranks into 2 x 2); the first minimum in the order
// of the factors of direction 0, then 1, breaks ties. Throws
// cosim::InputError when the ranks cannot fit (more ranks than cells).
std::array<int, 3> process_grid(int ranks, std::span<const std::int64_t> cells);

// One rank's part of the grid.
struct Block {
  std::array<int, 3> coords{0, 0, 0};  // in the process grid
  std::array<Range, 3> cells{};        // owned cells per direction ({0, 1} beyond the grid's dim)
  // The rank across each face: x_min, x_max, y_min, y_max, z_min, z_max;
  // -1 at the grid's edge.
  std::array<int, 6> neighbour{-1, -1, -1, -1, -1, -1};
};

// A grid of cells[d] cells (d < dim) split into dims[d] even parts per
// direction. Throws cosim::InputError for a dim outside 1..3, a direction
// with fewer cells than parts, or non-positive counts.
class CartesianDecomposition {
 public:
  CartesianDecomposition(int dim, std::array<std::int64_t, 3> cells, std::array<int, 3> dims);

  int dimension() const { return dim_; }
  int ranks() const { return dims_[0] * dims_[1] * dims_[2]; }
  const std::array<int, 3>& dims() const { return dims_; }
  const std::array<std::int64_t, 3>& cells() const { return cells_; }

  int rank_of(const std::array<int, 3>& coords) const;
  std::array<int, 3> coords_of(int rank) const;
  Block block(int rank) const;
  // The rank that owns cell (i, j, k).
  int owner(const std::array<std::int64_t, 3>& cell) const;

 private:
  int dim_;
  std::array<std::int64_t, 3> cells_;
  std::array<int, 3> dims_;
};

}  // namespace cosim::decomposition
