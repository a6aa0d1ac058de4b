#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "cosim/decomposition/cartesian_decomposition.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "cosim/mesh.hpp"
#include "swe/solver.hpp"

namespace swe {

// How this process takes part in a run decomposed over several MPI ranks
// (issue 27): the reductions the outputs need and where they are written.
// This base class is a run on one process, where every reduction is the
// identity; swe::parallel::DecomposedRun is the other.
class RunRanks {
 public:
  virtual ~RunRanks() = default;

  virtual int ranks() const { return 1; }
  virtual int rank() const { return 0; }
  // Rank 0 writes the run's tables and the summary's figures.
  bool writes_outputs() const { return rank() == 0; }
  // Whether `local` holds on any rank (collective).
  virtual bool any(bool local) const { return local; }
  // Elementwise sums and maxima over the ranks, in place (collective).
  virtual void sum(std::span<double> /*values*/) const {}
  virtual void max(std::span<double> /*values*/) const {}
  // The cell of `solver` holding the point (x, y) of the whole grid, or
  // solver.cell_count() when another rank's block holds it.
  virtual std::size_t cell_at(const Solver& solver, double x, double y) const {
    return solver.cell_at(x, y);
  }
  // The snapshots of the whole grid, `cells` being this process's (collective).
  virtual std::unique_ptr<cosim::SnapshotSink> snapshots(const std::filesystem::path& directory,
                                                         const std::string& base_name,
                                                         const cosim::Mesh& cells) const {
    return std::make_unique<cosim::SnapshotWriter>(directory, base_name, cells);
  }
  // A coupled participant on several ranks declares the whole grid and the
  // cells its block holds (in the solver's order); none on one process.
  virtual std::optional<std::pair<cosim::Mesh, cosim::MeshPart>> coupling_cells(
      const std::string& /*mesh_name*/) const {
    return std::nullopt;
  }
  // The cells of the whole grid this process's block owns; none on one
  // process (the whole grid).
  virtual std::optional<std::array<cosim::decomposition::Range, 3>> block_cells() const {
    return std::nullopt;
  }
};

}  // namespace swe
