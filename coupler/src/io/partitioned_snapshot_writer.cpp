#include "cosim/io/partitioned_snapshot_writer.hpp"

#include <fmt/format.h>

#include <functional>
#include <utility>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "hdf5_file.hpp"
#include "xdmf_mesh.hpp"

namespace cosim {

namespace fs = std::filesystem;

namespace {

const UniformGrid& cell_grid(const Mesh& mesh) {
  const auto* grid = std::get_if<UniformGrid>(&mesh.geometry);
  if (!grid || grid->dim < 2 || grid->location != GridLocation::cell)
    throw InputError(fmt::format(
        "partitioned snapshots of mesh '{}': only 2D and 3D uniform grids of cells split",
        mesh.name));
  return *grid;
}

std::size_t block_cells(const std::array<decomposition::Range, 3>& block) {
  return static_cast<std::size_t>(block[0].size() * block[1].size() * block[2].size());
}

// The communicator of a partitioned writer (a duplicate of `comm`) once
// every rank has checked that all name the same files, and the directory
// exists (collective).
MPI_Comm shared_output(MPI_Comm comm, const fs::path& directory, const std::string& base_name) {
  if (base_name.empty() || base_name.find('/') != std::string::npos)
    throw InputError("snapshot base name '" + base_name + "' is empty or contains '/'");
  MPI_Comm shared = MPI_COMM_NULL;
  MPI_Comm_dup(comm, &shared);
  int rank = 0;
  MPI_Comm_rank(shared, &rank);
  // Ranks that name different files would wait forever in MPI-IO's open
  // (Open MPI's OMPIO, when the open fails on some of them): all refuse now.
  const std::string where = (directory / base_name).lexically_normal().string();
  unsigned long long name[2] = {std::hash<std::string>{}(where), 0};
  name[1] = ~name[0];
  MPI_Allreduce(MPI_IN_PLACE, name, 2, MPI_UNSIGNED_LONG_LONG, MPI_MAX, shared);
  if (name[0] != ~name[1]) {
    MPI_Comm_free(&shared);
    throw InputError(
        fmt::format("partitioned snapshots '{}': the ranks name different files (this rank: '{}')",
                    base_name, where));
  }
  hdf5::silence_error_printing();
  if (rank == 0) create_output_directory(directory);
  MPI_Barrier(shared);
  return shared;
}

// File access through MPI-IO and collective transfers.
struct CollectiveIo {
  hdf5::PropertyListHandle access, transfer;

  explicit CollectiveIo(MPI_Comm comm)
      : access(H5Pcreate(H5P_FILE_ACCESS), "file access properties"),
        transfer(H5Pcreate(H5P_DATASET_XFER), "transfer properties") {
    if (H5Pset_fapl_mpio(access.get(), comm, MPI_INFO_NULL) < 0) hdf5::fail("MPI-IO file access");
    if (H5Pset_dxpl_mpio(transfer.get(), H5FD_MPIO_COLLECTIVE) < 0)
      hdf5::fail("collective transfers");
  }
};

}  // namespace

PartitionedSnapshotWriter::PartitionedSnapshotWriter(
    MPI_Comm comm, fs::path directory, std::string base_name, Mesh mesh,
    const std::array<decomposition::Range, 3>& block)
    : directory_(std::move(directory)),
      base_name_(std::move(base_name)),
      mesh_(std::move(mesh)),
      block_(block) {
  validate(mesh_);
  const UniformGrid& grid = cell_grid(mesh_);
  for (std::size_t d = 0; d < 3; ++d) {
    const std::int64_t cells = static_cast<int>(d) < grid.dim ? grid.cells[d] : 1;
    if (block_[d].begin < 0 || block_[d].end > cells || block_[d].size() < 1)
      throw InputError(
          fmt::format("partitioned snapshots of mesh '{}': a block [{}, {}) outside its {} cells "
                      "in direction {}",
                      mesh_.name, block_[d].begin, block_[d].end, cells, d));
  }
  comm_ = shared_output(comm, directory_, base_name_);
  MPI_Comm_rank(comm_, &rank_);
}

PartitionedSnapshotWriter::~PartitionedSnapshotWriter() {
  if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
}

fs::path PartitionedSnapshotWriter::index_path() const {
  return directory_ / (base_name_ + ".xdmf");
}

fs::path PartitionedSnapshotWriter::snapshot_path(std::size_t step) const {
  return directory_ / fmt::format("{}_{:06}.h5", base_name_, step);
}

void PartitionedSnapshotWriter::write(double time, const SnapshotFields& fields) {
  const std::size_t cells = block_cells(block_);
  for (const auto& [name, field] : fields)
    if (field.components < 1 ||
        field.values.size() != cells * static_cast<std::size_t>(field.components))
      throw InputError(fmt::format(
          "partitioned snapshots '{}': field '{}' has {} values; the block has {} cells x {} "
          "components",
          base_name_, name, field.values.size(), cells, field.components));
  hdf5::silence_error_printing();
  const std::size_t step = written_;
  const fs::path path = snapshot_path(step);
  const fs::path staged = staging_path(path);
  {
    const CollectiveIo io(comm_);
    hdf5::OutputFile file(staged, io.access.get());
    file.set_attribute("time", time);
    file.set_attribute("step", static_cast<std::int64_t>(step));
    const int dim = cell_grid(mesh_).dim;
    for (const auto& [name, field] : fields) {
      const int stored = xdmf::stored_components(field.components);
      const std::vector<hsize_t> dims = xdmf::field_dims(mesh_, stored);
      // dims are slowest first: (z,) y, x [, components]
      std::vector<hsize_t> start, count;
      for (int d = dim - 1; d >= 0; --d) {
        start.push_back(static_cast<hsize_t>(block_[static_cast<std::size_t>(d)].begin));
        count.push_back(static_cast<hsize_t>(block_[static_cast<std::size_t>(d)].size()));
      }
      if (dims.size() > start.size()) {
        start.push_back(0);
        count.push_back(static_cast<hsize_t>(stored));
      }
      const hdf5::OutputFile::Part part{start, count, io.transfer.get()};
      if (stored == field.components)
        file.write("fields/" + name, dims, part, field.values, field.unit);
      else
        file.write("fields/" + name, dims, part, xdmf::padded_to_three_components(field.values),
                   field.unit);
    }
    file.close();
  }
  MPI_Barrier(comm_);
  ++written_;
  if (rank_ != 0) return;
  commit_staged_file(staged, path);
  grids_.push_back(
      xdmf::snapshot_grid(base_name_, step, time, mesh_, "", path.filename().string(), fields));
  xdmf::write_temporal_index(index_path(), base_name_, grids_);
}

PartitionedPointCloudWriter::PartitionedPointCloudWriter(MPI_Comm comm, fs::path directory,
                                                         std::string base_name,
                                                         std::string mesh_name, int dim,
                                                         std::size_t points)
    : directory_(std::move(directory)),
      base_name_(std::move(base_name)),
      mesh_name_(std::move(mesh_name)),
      dim_(dim),
      points_(points) {
  if (dim_ != 2 && dim_ != 3)
    throw InputError(
        fmt::format("partitioned snapshots of point cloud '{}': dimension {}", mesh_name_, dim_));
  comm_ = shared_output(comm, directory_, base_name_);
  MPI_Comm_rank(comm_, &rank_);
}

PartitionedPointCloudWriter::~PartitionedPointCloudWriter() {
  if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
}

fs::path PartitionedPointCloudWriter::index_path() const {
  return directory_ / (base_name_ + ".xdmf");
}

fs::path PartitionedPointCloudWriter::snapshot_path(std::size_t step) const {
  return directory_ / fmt::format("{}_{:06}.h5", base_name_, step);
}

// The datasets of SnapshotWriter's snapshot of a moving point cloud, in its
// order: geometry/xyz (zero-padded to 3), topology/connectivity (the point
// itself), then the fields; each rank writes its rows.
void PartitionedPointCloudWriter::write(double time, std::span<const std::uint64_t> rows,
                                        std::span<const double> positions,
                                        const SnapshotFields& fields) {
  const std::size_t n = rows.size();
  if (positions.size() != n * static_cast<std::size_t>(dim_))
    throw InputError(fmt::format("partitioned snapshots '{}': {} positions for {} points",
                                 base_name_, positions.size(), n));
  for (const auto& [name, field] : fields)
    if (field.components < 1 ||
        field.values.size() != n * static_cast<std::size_t>(field.components))
      throw InputError(fmt::format(
          "partitioned snapshots '{}': field '{}' has {} values; this rank has {} points x {} "
          "components",
          base_name_, name, field.values.size(), n, field.components));
  // Runs of consecutive rows: (first, count) pairs.
  std::vector<hsize_t> runs;
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0 && rows[k] <= rows[k - 1])
      throw Error(ExitCode::internal_error, "partitioned point cloud: rows not increasing");
    if (rows[k] >= points_)
      throw Error(ExitCode::internal_error, "partitioned point cloud: a row beyond the cloud");
    if (!runs.empty() && runs[runs.size() - 2] + runs.back() == rows[k]) {
      ++runs.back();
    } else {
      runs.push_back(rows[k]);
      runs.push_back(1);
    }
  }
  std::vector<double> xyz(3 * n, 0.0);
  std::vector<std::int64_t> connectivity(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int d = 0; d < dim_; ++d)
      xyz[3 * k + static_cast<std::size_t>(d)] = positions[dim_ * k + static_cast<std::size_t>(d)];
    connectivity[k] = static_cast<std::int64_t>(rows[k]);
  }
  hdf5::silence_error_printing();
  const std::size_t step = written_;
  const fs::path path = snapshot_path(step);
  const fs::path staged = staging_path(path);
  {
    const CollectiveIo io(comm_);
    const hdf5::OutputFile::Rows mine{runs, io.transfer.get()};
    hdf5::OutputFile file(staged, io.access.get());
    file.set_attribute("time", time);
    file.set_attribute("step", static_cast<std::int64_t>(step));
    const hsize_t xyz_dims[] = {points_, 3};
    file.write("geometry/xyz", xyz_dims, mine, xyz, "m");
    const hsize_t point_dims[] = {points_};
    file.write("topology/connectivity", point_dims, mine, connectivity);
    for (const auto& [name, field] : fields) {
      const int stored = xdmf::stored_components(field.components);
      std::vector<hsize_t> dims{points_};
      if (stored > 1) dims.push_back(static_cast<hsize_t>(stored));
      if (stored == field.components)
        file.write("fields/" + name, dims, mine, field.values, field.unit);
      else
        file.write("fields/" + name, dims, mine, xdmf::padded_to_three_components(field.values),
                   field.unit);
    }
    file.close();
  }
  MPI_Barrier(comm_);
  ++written_;
  if (rank_ != 0) return;
  commit_staged_file(staged, path);
  // The XDMF text needs the cloud's size only.
  PointCloud sized;
  sized.dim = dim_;
  sized.volumes.assign(points_, 0.0);
  grids_.push_back(xdmf::snapshot_grid(base_name_, step, time, Mesh{mesh_name_, std::move(sized)},
                                       path.filename().string(), path.filename().string(), fields));
  xdmf::write_temporal_index(index_path(), base_name_, grids_);
}

}  // namespace cosim
