#pragma once

#include <mpi.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "cosim/decomposition/cartesian_decomposition.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "cosim/mesh.hpp"

namespace cosim {

// The files of a partitioned writer: the ranks naming them, each snapshot
// written together, rank 0's index (partitioned_snapshot_writer.cpp).
class PartitionedFiles;

// The snapshots of a uniform grid of cells decomposed over the ranks of a
// communicator (issue 27): every rank passes its block's values, and each
// snapshot is one HDF5 file the ranks write together (parallel HDF5, MPI-IO
// collective writes), with the same datasets, attributes and XDMF index as
// SnapshotWriter's (rank 0 keeps the index), so that ParaView opens a
// decomposed run exactly as one on one process. No rank holds more than
// its block. Files are staged and renamed once complete, as SnapshotWriter's.
class PartitionedSnapshotWriter final : public SnapshotSink {
 public:
  // `mesh`: the whole grid (a UniformGrid of 2 or 3 dimensions, values at
  // the cells or at the nodes); `block`: this rank's values (cells or nodes)
  // per direction (x first). The ranks' blocks must tile the grid's values.
  // Collective. Throws InputError for another mesh or a block outside the
  // grid.
  PartitionedSnapshotWriter(MPI_Comm comm, std::filesystem::path directory, std::string base_name,
                            Mesh mesh, const std::array<decomposition::Range, 3>& block);
  ~PartitionedSnapshotWriter();
  PartitionedSnapshotWriter(const PartitionedSnapshotWriter&) = delete;
  PartitionedSnapshotWriter& operator=(const PartitionedSnapshotWriter&) = delete;

  // Appends a snapshot at `time` [s]. Each field holds the block's values x
  // components values, the block's values x fastest (InputError naming the
  // field otherwise). Every rank calls it with the same fields (collective).
  void write(double time, const SnapshotFields& fields) override;

  // This rank's block from the next snapshot on (the ranks' blocks must
  // still tile the grid: a decomposition whose cuts moved). InputError for a
  // block outside the grid.
  void set_block(const std::array<decomposition::Range, 3>& block);

  std::size_t snapshots_written() const override;
  std::filesystem::path index_path() const;
  std::filesystem::path snapshot_path(std::size_t step) const;

 private:
  Mesh mesh_;
  std::array<decomposition::Range, 3> block_;
  std::unique_ptr<PartitionedFiles> files_;
};

// The snapshots of a point cloud whose points are spread over the ranks of
// a communicator (a decomposed MPM, issue 27): each rank passes its points
// and their rows in the whole cloud, and each snapshot is one HDF5 file the
// ranks write together, the same as SnapshotWriter's of the whole moving
// cloud (geometry stored in every snapshot). Rank 0 keeps the index.
class PartitionedPointCloudWriter final : public PointCloudSink {
 public:
  // A cloud of `points` points of dimension `dim` (2 or 3) named
  // `mesh_name`. Collective. Throws InputError for another dimension or a
  // bad base name, or when the ranks name different files.
  PartitionedPointCloudWriter(MPI_Comm comm, std::filesystem::path directory, std::string base_name,
                              std::string mesh_name, int dim, std::size_t points);
  ~PartitionedPointCloudWriter();
  PartitionedPointCloudWriter(const PartitionedPointCloudWriter&) = delete;
  PartitionedPointCloudWriter& operator=(const PartitionedPointCloudWriter&) = delete;

  // Appends a snapshot at `time` [s] of this rank's points: `rows`, their
  // rows in the whole cloud (increasing), `positions` (rows x dim) and each
  // field's rows x components values. Every rank calls it with the same
  // fields (collective); InputError naming a field of another size.
  void write(double time, std::span<const std::uint64_t> rows, std::span<const double> positions,
             const SnapshotFields& fields) override;

  std::size_t snapshots_written() const override;
  std::filesystem::path index_path() const;
  std::filesystem::path snapshot_path(std::size_t step) const;

 private:
  std::string mesh_name_;
  int dim_;
  std::size_t points_;
  std::unique_ptr<PartitionedFiles> files_;
};

}  // namespace cosim
