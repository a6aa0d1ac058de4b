#pragma once

#include <mpi.h>

#include <cstddef>
#include <functional>
#include <vector>

#include "cosim/decomposition/cartesian_decomposition.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::parallel {

// The material points of a grid decomposed over MPI ranks (issue 27): a
// point belongs to the rank that owns the grid cell holding it, and moves
// there, with its whole state (every array of Particles), once it has
// crossed into that rank's block. The points a rank keeps stay in their
// order; those it receives follow, by sending rank, then in the sender's
// order, so that a run is the same on every repetition. A rank may hold no
// point at all.
template <int Dim>
class ParticleMigration {
 public:
  // The rank (of `comm`) that owns the point at x.
  using Owner = std::function<int(const Vec<Dim>&)>;
  ParticleMigration(MPI_Comm comm, Owner owner);
  // The blocks of `decomposition`, which splits the grid of cells of size
  // `cell_size` from `origin`; `comm` holds its ranks (in its order).
  ParticleMigration(MPI_Comm comm,
                    const cosim::decomposition::CartesianDecomposition& decomposition,
                    const Vec<Dim>& origin, double cell_size);
  ~ParticleMigration();
  ParticleMigration(const ParticleMigration&) = delete;
  ParticleMigration& operator=(const ParticleMigration&) = delete;

  // The rank owning the point at x (with a decomposition: the cell at x;
  // points outside the grid belong to the rank of the nearest cell).
  int owner(const Vec<Dim>& x) const { return owner_(x); }

  struct Moved {
    std::size_t sent = 0, received = 0;
    std::size_t bytes_sent = 0;
  };
  // Sends away every point of `particles` another rank owns and appends
  // those it sends here (collective).
  Moved migrate(Particles<Dim>& particles);

  // The ranks this rank's points usually move to (a slab's two
  // neighbours). When no point of any rank goes further, a migration talks
  // to them alone (point to point) instead of to every rank (MPI_Alltoall,
  // P - 1 latencies); whether one does is agreed by a small reduction.
  void set_neighbours(std::vector<int> neighbours);

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, ranks_ = 1;
  Owner owner_;
  std::vector<int> neighbours_;  // increasing
  Moved exchange_with_neighbours(Particles<Dim>& particles, const std::vector<int>& sent_points,
                                 Moved moved);

  std::vector<int> destination_;  // per point, of the last migrate()
  std::vector<std::vector<std::byte>> outgoing_;
  std::vector<std::byte> send_, receive_;
};

extern template class ParticleMigration<2>;
extern template class ParticleMigration<3>;

}  // namespace mpm::parallel
