#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cosim/mesh.hpp"

namespace cosim {

// One field of a snapshot: `components` values per mesh element,
// element-major (the same layout the participant API uses).
struct FieldView {
  std::span<const double> values;
  int components = 1;
  std::string_view unit = {};  // SI; stored as the dataset's "unit" attribute when given
};

using SnapshotFields = std::map<std::string, FieldView, std::less<>>;

// Where a run's snapshots go: one process's SnapshotWriter, or the
// PartitionedSnapshotWriter of a run decomposed over MPI ranks.
class SnapshotSink {
 public:
  virtual ~SnapshotSink() = default;
  // Appends a snapshot at `time` [s] (see the writers for the fields' sizes).
  virtual void write(double time, const SnapshotFields& fields) = 0;
  virtual std::size_t snapshots_written() const = 0;
};

// Where the snapshots of a moving point cloud spread over ranks go
// (PartitionedPointCloudWriter): each rank passes its points, their rows in
// the whole cloud (increasing), positions (rows x dim) and each field's rows
// x components values; every rank calls write() together.
class PointCloudSink {
 public:
  virtual ~PointCloudSink() = default;
  virtual void write(double time, std::span<const std::uint64_t> rows,
                     std::span<const double> positions, const SnapshotFields& fields) = 0;
  virtual std::size_t snapshots_written() const = 0;
};

// Field snapshots of one mesh as HDF5 files with an XDMF 3 index that
// ParaView opens (architecture.md §6).
//
// Files, all in `directory`:
//   <base>.xdmf          temporal collection of every snapshot written so far;
//                        rewritten atomically (staged, then renamed) after each
//                        snapshot, so a run that dies keeps a valid index
//   <base>_<step>.h5     one file per snapshot (step = 000000, 000001, ...),
//                        staged and renamed once complete, so a crash can only
//                        lose the snapshot being written; layout:
//                          attributes  time [s], step
//                          /fields/<name>    float64, dims as in the XDMF
//                          /geometry/xyz, /topology/connectivity
//                                      (point clouds, and meshes passed to write)
//   <base>_mesh.h5       geometry and connectivity of meshes without an
//                        implicit geometry (lines, cell clouds), written once
//
// Representation per mesh kind:
//   uniform grid, 2D/3D   2DCoRectMesh / 3DCoRectMesh with origin and spacing;
//                         cell-centred values Center="Cell" (dims = cells),
//                         node-centred values Center="Node" (dims = cells + 1);
//                         dataset dims are slowest first: (nz,) ny, nx [, c]
//   uniform grid 1D and   Polyline of 2-node segments through the cell edges;
//   non-uniform line      cell values Center="Cell", node values Center="Node"
//   point / cell cloud    Polyvertex with XYZ geometry, values Center="Node"
// Coordinates of 1D and 2D meshes are padded with zeros to XYZ. Components:
// 1 Scalar, 2 or 3 Vector (2D vectors are padded with a zero third component
// in the file, which ParaView needs), 6 Tensor6, 9 Tensor, any other Matrix.
//
// HDF5 errors become cosim::Error carrying the HDF5 error stack's message;
// HDF5's automatic printing of its error stack is switched off. Not for use
// by several threads at once.
class SnapshotWriter final : public SnapshotSink {
 public:
  // Validates the mesh (InputError) and creates the directory (Error).
  SnapshotWriter(std::filesystem::path directory, std::string base_name, Mesh mesh);

  // Appends a snapshot at `time` [s]. Each field needs
  // mesh.size() * components values (InputError naming the field otherwise);
  // names must be non-empty, without '/' or ':', and not "." or "..".
  void write(double time, const SnapshotFields& fields) override;
  // Same, on a changed mesh of the same kind (moving particles, a moving
  // grid): the new geometry is stored with this snapshot and used by the
  // snapshots after it.
  void write(double time, const Mesh& current_mesh, const SnapshotFields& fields);

  std::size_t snapshots_written() const override { return grids_.size(); }
  std::filesystem::path index_path() const;
  std::filesystem::path snapshot_path(std::size_t step) const;
  const Mesh& mesh() const { return mesh_; }

 private:
  void check_fields(const Mesh& mesh, const SnapshotFields& fields) const;
  void write_snapshot(double time, const Mesh& mesh, const SnapshotFields& fields,
                      bool store_geometry);
  std::string grid_xml(std::size_t step, double time, const Mesh& mesh,
                       const SnapshotFields& fields) const;
  void rewrite_index() const;

  std::filesystem::path directory_;
  std::string base_name_;
  Mesh mesh_;
  std::string geometry_file_;       // HDF5 file (in directory_) with the current explicit geometry
  std::vector<std::string> grids_;  // rendered <Grid> element of every snapshot
};

}  // namespace cosim
