#pragma once

#include <mpi.h>

#include <chrono>
#include <memory>

#include "swe/case/case_description.hpp"
#include "swe/parallel/gathered_grid_2d.hpp"
#include "swe/parallel/mpi_subdomain_link.hpp"

// swe_fluid started standalone by `mpirun -np N` (issue 27): the case's 2D
// grid split into N blocks, one per rank, stepped together with the same
// time steps; rank 0 gathers the whole grid for the outputs and writes the
// files a run on one rank writes.
namespace swe::parallel {

// The ranks mpirun started (from its environment, before MPI starts); 1
// outside mpirun.
int ranks_from_launcher();

// MPI for the run: initialised by the constructor, finalised by the
// destructor.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int ranks() const { return ranks_; }
  // The end of the run on this rank with exit code `code`: waits for every
  // rank to end and returns the largest code. A rank that failed waits at
  // most `grace` for the others, then ends them all with its code
  // (MPI_Abort): failing alone, it would leave them waiting in a
  // collective forever.
  int finish(int code, std::chrono::milliseconds grace = std::chrono::seconds(2)) const;

 private:
  int rank_ = 0, ranks_ = 1;
};

// This rank's block of the case's grid and the gathered whole grid.
// Throws cosim::InputError, naming the case file, for a case that cannot run
// decomposed (1D, two-phase) and for blocks narrower than the ghost layers.
class DecomposedRun {
 public:
  DecomposedRun(MPI_Comm comm, const CaseDescription& description);

  std::unique_ptr<Solver> take_solver() { return std::move(solver_); }
  GatheredGrid2d& whole() { return *whole_; }
  // Whether `local` holds on any rank (collective).
  bool any(bool local) const;
  const cosim::decomposition::Block& block() const { return link_->halo().block(); }
  const cosim::decomposition::CartesianDecomposition& decomposition() const {
    return decomposition_;
  }

 private:
  MPI_Comm comm_;
  cosim::decomposition::CartesianDecomposition decomposition_;
  std::shared_ptr<MpiSubdomainLink> link_;
  std::unique_ptr<Solver> solver_;
  std::unique_ptr<GatheredGrid2d> whole_;
};

}  // namespace swe::parallel
