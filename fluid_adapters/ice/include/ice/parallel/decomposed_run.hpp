#pragma once

#include <mpi.h>

#include <vector>

#include "ice/io/run_ranks.hpp"
#include "ice/parallel/mpi_block_link.hpp"

// ice_fluid started standalone by `mpirun -np N` (issue 27): the case's
// grid split into N blocks, one per rank, stepped together with the same
// time steps, the pressure solved by PETSc over all of them. The ranks write
// one set of files, those of a run on one process: each snapshot
// collectively into one HDF5 file, the tables by rank 0 from reductions.
namespace ice::parallel {

template <int Dim>
class DecomposedRun final : public RunRanks<Dim> {
 public:
  // Collective. Throws cosim::InputError, naming the case file and key, for
  // a case that cannot run decomposed yet (1D, the built-in
  // pressure solver asked for) and for blocks narrower than the ghost layers
  // (grid.cells).
  DecomposedRun(MPI_Comm comm, const CaseDescription& description);

  int ranks() const override { return block_.decomposition.ranks(); }
  int rank() const override { return block_.link->halo().rank(); }
  std::unique_ptr<IceSolver<Dim>> make_solver(const CaseDescription& description) override;
  std::unique_ptr<cosim::SnapshotSink> snapshots(const std::filesystem::path& directory,
                                                 const std::string& base_name,
                                                 const cosim::Mesh& cells) override;
  const cosim::SnapshotFields& owned(const cosim::SnapshotFields& fields) override;
  std::optional<typename GaugeRecorder<Dim>::Decomposed> gauge_cells(
      const IceSolver<Dim>& solver) const override;
  void sum(std::span<double> values) override;
  std::optional<typename RunRanks<Dim>::CellsPart> coupling_cells(
      const IceSolver<Dim>& solver, const std::string& mesh_name) const override;
  std::optional<cosim::decomposition::StoredBlock> block() const override;

  const MpiBlockLink<Dim>& link() const { return *block_.link; }
  const cosim::decomposition::CartesianDecomposition& decomposition() const {
    return block_.decomposition;
  }

 private:
  MPI_Comm comm_;
  CellGrid<Dim> whole_;
  BlockSolver<Dim> block_;
  std::vector<std::vector<double>> owned_values_;
  cosim::SnapshotFields owned_fields_;
};

// The pressure solve of a run on one process by PETSc (`solver: petsc`):
// one block, no ghosts, on MPI_COMM_SELF. PETSc must be initialised.
template <int Dim>
std::unique_ptr<PressureSystemSolver<Dim>> petsc_pressure_on_one_process(
    const CaseDescription& description);

// The PETSc options of the case's pressure solve.
PetscPressureOptions petsc_pressure_options(const CaseDescription& description);

extern template class DecomposedRun<1>;
extern template class DecomposedRun<2>;
extern template class DecomposedRun<3>;

}  // namespace ice::parallel
