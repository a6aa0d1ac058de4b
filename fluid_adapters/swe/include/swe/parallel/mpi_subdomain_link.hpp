#pragma once

#include <mpi.h>

#include <memory>

#include "cosim/decomposition/halo_exchange.hpp"
#include "swe/solver_2d.hpp"
#include "swe/subdomain_link.hpp"

// The 2D shallow-water solver decomposed over MPI ranks (issue 27): each
// rank runs a Solver2d on its block of the grid, linked to the others by a
// halo exchange of two layers and reductions over the communicator.
namespace swe::parallel {

class MpiSubdomainLink final : public SubdomainLink {
 public:
  // The rank's block of `decomposition` (over every rank of `comm`).
  // Throws cosim::InputError for a block narrower than the two ghost layers.
  MpiSubdomainLink(MPI_Comm comm,
                   const cosim::decomposition::CartesianDecomposition& decomposition);
  ~MpiSubdomainLink() override;
  MpiSubdomainLink(const MpiSubdomainLink&) = delete;
  MpiSubdomainLink& operator=(const MpiSubdomainLink&) = delete;

  std::array<bool, 4> linked_sides() const override;
  void fill_ghosts(std::span<const std::span<double>> arrays) override;
  double max(double local) override;
  void sum(std::span<double> values) override;

  const cosim::decomposition::HaloExchange& halo() const { return halo_; }
  MPI_Comm communicator() const { return comm_; }
  // Seconds spent in fill_ghosts and the reductions, and the values sent, since construction.
  double communication_seconds() const { return seconds_; }
  std::size_t values_sent() const { return values_sent_; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  cosim::decomposition::HaloExchange halo_;
  double seconds_ = 0.0;
  std::size_t values_sent_ = 0;
};

// One rank's part of a grid decomposed over `comm`'s ranks: the solver of
// its block and the block (global cell ranges and neighbours).
struct BlockSolver2d {
  std::unique_ptr<Solver2d> solver;
  std::shared_ptr<MpiSubdomainLink> link;
  cosim::decomposition::Block block;
};

// `grid` split over `ranks` ranks (cosim::decomposition::process_grid: the
// least halo). Throws cosim::InputError when a block would hold fewer than 2
// cells in a direction that is split.
cosim::decomposition::CartesianDecomposition decompose_grid(const Grid2d& grid, int ranks);

// Splits `grid` over the ranks of `comm` (cosim::decomposition::process_grid:
// the least halo) and builds this rank's block solver with the boundaries of
// the sides on the grid's edge. Collective. Throws cosim::InputError when a
// block would hold fewer than 2 cells in a direction.
BlockSolver2d make_block_solver(MPI_Comm comm, const Grid2d& grid, const Physics& physics,
                                const Scheme& scheme, const Boundaries2d& boundaries);

// The block's part of `grid`: its cells and origin.
Grid2d block_grid(const Grid2d& grid, const cosim::decomposition::Block& block);

}  // namespace swe::parallel
