// The halo exchange on 1, 2, 3 and 4 ranks (mpirun, label mpi): every rank
// fills its owned cells with a function of the global cell and component,
// its ghosts with NaN; after the exchange every ghost inside the grid holds
// the function's value (edges and corners too), and every ghost beyond the
// grid's edge is still NaN.
#include "cosim/decomposition/halo_exchange.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <limits>
#include <vector>

#include "cosim/error.hpp"

namespace cosim::decomposition {
namespace {

double value(std::int64_t i, std::int64_t j, std::int64_t k, int c) {
  return 1e6 * c + 1e4 * static_cast<double>(k) + 1e2 * static_cast<double>(j) +
         static_cast<double>(i);
}

// `components` values per cell side by side in one field, or, with
// `separate_fields`, one field per component exchanged together (SoA).
void check_exchange(int dim, std::array<std::int64_t, 3> cells, int halo, int components,
                    bool separate_fields = false, GhostSides sides = GhostSides::every_side) {
  int ranks = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const auto dims = process_grid(ranks, std::span<const std::int64_t>(cells.data(), dim));
  const CartesianDecomposition decomposition(dim, cells, dims);
  const HaloExchange exchange(MPI_COMM_WORLD, decomposition, halo, sides);
  const Block& b = exchange.block();
  const std::size_t padded = exchange.padded_size();
  std::vector<double> field(padded * static_cast<std::size_t>(components),
                            std::numeric_limits<double>::quiet_NaN());
  // Cell `cell`'s component c, in either arrangement.
  auto at = [&](std::size_t cell, int c) -> double& {
    const auto cu = static_cast<std::size_t>(c);
    return separate_fields ? field[cu * padded + cell]
                           : field[cell * static_cast<std::size_t>(components) + cu];
  };
  for (auto k = b.cells[2].begin; k < b.cells[2].end; ++k)
    for (auto j = b.cells[1].begin; j < b.cells[1].end; ++j)
      for (auto i = b.cells[0].begin; i < b.cells[0].end; ++i)
        for (int c = 0; c < components; ++c) at(exchange.index(i, j, k), c) = value(i, j, k, c);
  if (separate_fields) {
    std::vector<std::span<double>> fields;
    for (int c = 0; c < components; ++c)
      fields.emplace_back(field.data() + static_cast<std::size_t>(c) * padded, padded);
    exchange.exchange(fields);
  } else {
    exchange.exchange(field, components);
  }
  std::array<std::int64_t, 3> lo{0, 0, 0}, hi{1, 1, 1};
  for (std::size_t d = 0; d < 3; ++d)
    if (static_cast<int>(d) < dim) {
      lo[d] = b.cells[d].begin - exchange.ghosts_below()[d];
      hi[d] = lo[d] + exchange.padded_extent()[d];
    }
  int wrong = 0;
  for (auto k = lo[2]; k < hi[2]; ++k)
    for (auto j = lo[1]; j < hi[1]; ++j)
      for (auto i = lo[0]; i < hi[0]; ++i) {
        if (sides == GhostSides::toward_neighbours) {
          // Only the sides toward a neighbour hold ghosts.
          EXPECT_TRUE(i >= 0 && i < cells[0] && j >= 0 && j < cells[1] && k >= 0 && k < cells[2]);
        }
        const bool inside = i >= 0 && i < cells[0] && (dim < 2 || (j >= 0 && j < cells[1])) &&
                            (dim < 3 || (k >= 0 && k < cells[2]));
        for (int c = 0; c < components; ++c) {
          const double v = at(exchange.index(i, j, k), c);
          if (inside ? v != value(i, j, k, c) : !std::isnan(v)) ++wrong;
        }
      }
  EXPECT_EQ(wrong, 0) << "rank " << exchange.rank() << " of " << ranks;
}

TEST(HaloExchange, FillsEveryGhostInsideTheGridIn1D) {
  check_exchange(1, {23, 1, 1}, 2, 1);
}
TEST(HaloExchange, FillsEveryGhostInsideTheGridIn2D) {
  check_exchange(2, {13, 9, 1}, 2, 3);
}
TEST(HaloExchange, FillsTheGhostsOfSeveralFieldsInOneMessagePerFace) {
  check_exchange(2, {13, 9, 1}, 2, 3, true);
  check_exchange(3, {7, 6, 5}, 1, 2, true);
}
TEST(HaloExchange, FillsEveryGhostInsideTheGridIn3D) {
  check_exchange(3, {7, 6, 5}, 1, 2);
}
TEST(HaloExchange, FillsTheGhostsOfABlockWidenedTowardItsNeighboursOnly) {
  check_exchange(1, {23, 1, 1}, 3, 1, false, GhostSides::toward_neighbours);
  check_exchange(2, {13, 9, 1}, 2, 2, true, GhostSides::toward_neighbours);
  check_exchange(3, {7, 6, 5}, 1, 2, false, GhostSides::toward_neighbours);
}

// Every rank adds 1 + the cell's index to every cell of its padded block
// inside the grid; after accumulate() each owned cell holds that times the
// number of padded blocks that cover it (exact: small integers).
void check_accumulate(int dim, std::array<std::int64_t, 3> cells, int halo,
                      GhostSides sides = GhostSides::every_side) {
  int ranks = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const auto dims = process_grid(ranks, std::span<const std::int64_t>(cells.data(), dim));
  const CartesianDecomposition decomposition(dim, cells, dims);
  const HaloExchange exchange(MPI_COMM_WORLD, decomposition, halo, sides);
  auto padded = [&](const Block& b, std::size_t d) {
    return static_cast<int>(d) < dim ? Range{b.cells[d].begin - halo, b.cells[d].end + halo}
                                     : Range{0, 1};
  };
  auto inside = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return i >= 0 && i < cells[0] && j >= 0 && j < cells[1] && k >= 0 && k < cells[2];
  };
  auto contribution = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return 1.0 + static_cast<double>(i + cells[0] * (j + cells[1] * k));
  };
  const Block& mine = exchange.block();
  std::vector<double> mass(exchange.padded_size(), 0.0), momentum(exchange.padded_size(), 0.0);
  const Range r0 = padded(mine, 0), r1 = padded(mine, 1), r2 = padded(mine, 2);
  for (auto k = r2.begin; k < r2.end; ++k)
    for (auto j = r1.begin; j < r1.end; ++j)
      for (auto i = r0.begin; i < r0.end; ++i)
        if (inside(i, j, k)) {
          mass[exchange.index(i, j, k)] = contribution(i, j, k);
          momentum[exchange.index(i, j, k)] = -2.0 * contribution(i, j, k);
        }
  const std::span<double> fields[2] = {mass, momentum};
  exchange.accumulate(fields);
  int wrong = 0;
  for (auto k = mine.cells[2].begin; k < mine.cells[2].end; ++k)
    for (auto j = mine.cells[1].begin; j < mine.cells[1].end; ++j)
      for (auto i = mine.cells[0].begin; i < mine.cells[0].end; ++i) {
        int covering = 0;
        for (int r = 0; r < ranks; ++r) {
          const Block b = decomposition.block(r);
          const Range p0 = padded(b, 0), p1 = padded(b, 1), p2 = padded(b, 2);
          if (i >= p0.begin && i < p0.end && j >= p1.begin && j < p1.end && k >= p2.begin &&
              k < p2.end)
            ++covering;
        }
        const double expected = covering * contribution(i, j, k);
        if (mass[exchange.index(i, j, k)] != expected) ++wrong;
        if (momentum[exchange.index(i, j, k)] != -2.0 * expected) ++wrong;
      }
  EXPECT_EQ(wrong, 0) << "rank " << exchange.rank() << " of " << ranks;
}

TEST(HaloExchange, AccumulateAddsEveryGhostToItsOwnerIn2D) {
  check_accumulate(2, {13, 9, 1}, 2);
  check_accumulate(2, {8, 8, 1}, 1);
}
TEST(HaloExchange, AccumulateAddsEveryGhostToItsOwnerIn3D) {
  check_accumulate(3, {7, 6, 5}, 1);
}
TEST(HaloExchange, AccumulateAddsTheGhostsOfABlockWidenedTowardItsNeighbours) {
  check_accumulate(2, {13, 9, 1}, 2, GhostSides::toward_neighbours);
  check_accumulate(3, {7, 6, 5}, 1, GhostSides::toward_neighbours);
}

TEST(HaloExchange, RefusesAHaloWiderThanABlock) {
  int ranks = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const CartesianDecomposition thin(1, {static_cast<std::int64_t>(2 * ranks), 1, 1}, {ranks, 1, 1});
  EXPECT_THROW(HaloExchange(MPI_COMM_WORLD, thin, 3), InputError);
}

}  // namespace
}  // namespace cosim::decomposition
