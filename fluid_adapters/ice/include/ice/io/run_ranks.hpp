#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "cosim/decomposition/block_join.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "cosim/mesh.hpp"
#include "ice/case/case_description.hpp"
#include "ice/io/state_output.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {

// How this process takes part in a run decomposed over several MPI ranks
// (issue 27): its part of the case, and where and how its outputs go. This
// base class is a run on one process; ice::parallel::DecomposedRun is the
// other.
template <int Dim>
class RunRanks {
 public:
  virtual ~RunRanks() = default;

  virtual int ranks() const { return 1; }
  virtual int rank() const { return 0; }
  // Rank 0 writes the run's tables and the summary's figures.
  bool writes_outputs() const { return rank() == 0; }
  // The solver of this process's part of the case.
  virtual std::unique_ptr<IceSolver<Dim>> make_solver(const CaseDescription& description);
  // The snapshots of the whole grid (`cells`), each process writing its own
  // cells (collective).
  virtual std::unique_ptr<cosim::SnapshotSink> snapshots(const std::filesystem::path& directory,
                                                         const std::string& base_name,
                                                         const cosim::Mesh& cells);
  // The values of this process's own cells in `fields` (fields of the
  // solver's grid).
  virtual const cosim::SnapshotFields& owned(const cosim::SnapshotFields& fields) { return fields; }
  // Where the gauges lie when the grid is decomposed (none: one process).
  virtual std::optional<typename GaugeRecorder<Dim>::Decomposed> gauge_cells(
      const IceSolver<Dim>& /*solver*/) const {
    return std::nullopt;
  }
  // Elementwise sums over the ranks, in place (collective).
  virtual void sum(std::span<double> /*values*/) {}
  // A coupled participant on several ranks declares the whole grid and the
  // cells its solver holds (its block widened by ghost layers, in the
  // solver's order), of which it owns its block; none on one process.
  struct CellsPart {
    cosim::Mesh whole;
    cosim::MeshPart part;
  };
  virtual std::optional<CellsPart> coupling_cells(const IceSolver<Dim>& /*solver*/,
                                                  const std::string& /*mesh_name*/) const {
    return std::nullopt;
  }
  // Where the solver's grid lies in the case's: the cells this process owns
  // and those it holds (owned and ghost layers); none on one process (the
  // whole grid).
  virtual std::optional<cosim::decomposition::StoredBlock> block() const { return std::nullopt; }
};

extern template class RunRanks<1>;
extern template class RunRanks<2>;
extern template class RunRanks<3>;

}  // namespace ice
