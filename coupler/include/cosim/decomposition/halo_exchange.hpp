#pragma once

#include <mpi.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "cosim/decomposition/cartesian_decomposition.hpp"

namespace cosim::decomposition {

// Where a block stores ghost layers: on every side (a ghost layer on the
// grid's own edge is then left to the solver's boundary conditions), or only
// on the sides another block lies across (a solver whose grid is its block
// widened toward its neighbours, its own sides keeping their conditions).
enum class GhostSides { every_side, toward_neighbours };

// One rank's block of a CartesianDecomposition with `halo` layers of ghost
// cells on its sides (GhostSides), and the exchange that fills the ghost
// cells on the faces it shares with other ranks from their owned cells. The
// block is stored with its ghosts, x fastest (padded_extent()). Corners and
// edges are filled too: the directions are exchanged one after the other,
// each over the whole padded extent of the others, so a later direction
// carries what an earlier one brought.
class HaloExchange {
 public:
  // `comm` holds decomposition.ranks() ranks; a Cartesian communicator is
  // made from it in the decomposition's order (MPI_Cart_create without
  // reordering). Throws cosim::InputError for a communicator of another
  // size, a negative halo, or a halo wider than a block.
  HaloExchange(MPI_Comm comm, const CartesianDecomposition& decomposition, int halo,
               GhostSides sides = GhostSides::every_side);
  ~HaloExchange();
  HaloExchange(const HaloExchange&) = delete;
  HaloExchange& operator=(const HaloExchange&) = delete;

  int rank() const { return rank_; }
  const Block& block() const { return block_; }
  int halo() const { return halo_; }
  // Cells per direction with the ghosts (owned + the ghost layers below and
  // above; 1 beyond the grid's dim).
  const std::array<std::int64_t, 3>& padded_extent() const { return extent_; }
  // Ghost layers below the first owned cell per direction (halo or 0).
  const std::array<std::int64_t, 3>& ghosts_below() const { return below_; }
  std::size_t padded_size() const;
  // Index in the padded block of the cell with global indices (i, j, k),
  // which may lie in the ghost layers.
  std::size_t index(std::int64_t i, std::int64_t j = 0, std::int64_t k = 0) const;

  // Fills the ghost cells of `field`, `components` values per cell (side by
  // side), from the neighbours. Every rank calls it (collective).
  void exchange(std::span<double> field, int components) const;
  // Fills the ghost cells of several fields of one value per cell (SoA
  // arrays), packed into one message per face: the latency of one exchange
  // for all of them.
  void exchange(std::span<const std::span<double>> fields) const;

  // The reverse of exchange(), for quantities that points or cells scatter
  // onto their neighbours (an MPM's nodal mass and momentum after P2G): what
  // each rank holds in its ghost cells inside the grid, edges and corners
  // included, is added to the owner's cells. The ghosts are left with
  // partial sums: exchange() afterwards gives them the totals. The sums run
  // in a fixed order for a given decomposition.
  void accumulate(std::span<const std::span<double>> fields) const;

  // Values this rank sent in its last exchange (the halo's volume per call).
  std::size_t values_sent() const { return values_sent_; }

 private:
  MPI_Comm cart_ = MPI_COMM_NULL;
  int rank_ = 0;
  int dim_ = 1;
  int halo_ = 0;
  Block block_;
  std::array<std::int64_t, 3> extent_{1, 1, 1};
  std::array<std::int64_t, 3> below_{0, 0, 0};
  mutable std::vector<double> send_, receive_;
  mutable std::size_t values_sent_ = 0;

  // The fields' values per cell: `components` side by side in each of them.
  void exchange(std::span<const std::span<double>> fields, int components) const;
  void check(std::span<const std::span<double>> fields, int components) const;
  // One message along direction d, to the upper neighbour (`upward`) or the
  // lower: the slab from local layer `send_first` goes, the one received is
  // given to receive(field values, received values, count) at `receive_first`.
  template <class Receive>
  void transfer(std::span<const std::span<double>> fields, std::size_t per_cell, std::size_t d,
                bool upward, std::int64_t send_first, std::int64_t receive_first,
                Receive&& receive) const;
};

}  // namespace cosim::decomposition
