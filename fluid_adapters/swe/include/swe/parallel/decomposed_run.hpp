#pragma once

#include <mpi.h>

#include <memory>

#include "swe/case/case_description.hpp"
#include "swe/io/run_ranks.hpp"
#include "swe/parallel/mpi_subdomain_link.hpp"

// swe_fluid started standalone by `mpirun -np N` (issue 27): the case's 2D
// grid split into N blocks, one per rank, stepped together with the same
// time steps. The ranks write one set of files, those of a run on one
// process: each snapshot collectively into one HDF5 file, the tables by
// rank 0 from reductions. No rank holds more than its block.
namespace swe::parallel {

// This rank's block of the case's grid, and the reductions over the ranks.
// Throws cosim::InputError, naming the case file and key, for a case that
// cannot run decomposed (1D, two-phase) and for blocks narrower than the
// ghost layers.
class DecomposedRun final : public RunRanks {
 public:
  DecomposedRun(MPI_Comm comm, const CaseDescription& description);

  std::unique_ptr<Solver> take_solver() { return std::move(solver_); }
  const cosim::decomposition::Block& block() const { return link_->halo().block(); }
  const cosim::decomposition::CartesianDecomposition& decomposition() const {
    return decomposition_;
  }

  int ranks() const override { return decomposition_.ranks(); }
  int rank() const override { return link_->halo().rank(); }
  bool any(bool local) const override;
  void sum(std::span<double> values) const override;
  void max(std::span<double> values) const override;
  std::size_t cell_at(const Solver& solver, double x, double y) const override;
  std::unique_ptr<cosim::SnapshotSink> snapshots(const std::filesystem::path& directory,
                                                 const std::string& base_name,
                                                 const cosim::Mesh& cells) const override;
  std::optional<std::pair<cosim::Mesh, cosim::MeshPart>> coupling_cells(
      const std::string& mesh_name) const override;
  std::optional<std::array<cosim::decomposition::Range, 3>> block_cells() const override {
    return block().cells;
  }

 private:
  MPI_Comm comm_;
  Grid2d grid_;  // the whole grid
  cosim::decomposition::CartesianDecomposition decomposition_;
  std::shared_ptr<MpiSubdomainLink> link_;
  std::unique_ptr<Solver> solver_;
};

}  // namespace swe::parallel
