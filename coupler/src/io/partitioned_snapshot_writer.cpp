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

const UniformGrid& split_grid(const Mesh& mesh) {
  const auto* grid = std::get_if<UniformGrid>(&mesh.geometry);
  if (!grid || grid->dim < 2)
    throw InputError(fmt::format(
        "partitioned snapshots of mesh '{}': only 2D and 3D uniform grids split", mesh.name));
  return *grid;
}

std::size_t block_cells(const std::array<decomposition::Range, 3>& block) {
  return static_cast<std::size_t>(block[0].size() * block[1].size() * block[2].size());
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

// Writes each field under fields/, 2D vectors padded to 3 components, with
// `dims_of(stored components)` and this rank's `selection` (a Part or Rows).
template <class Selection, class Dims>
void write_fields(hdf5::OutputFile& file, const SnapshotFields& fields, Dims&& dims_of,
                  Selection&& selection_of) {
  for (const auto& [name, field] : fields) {
    const int stored = xdmf::stored_components(field.components);
    const std::vector<hsize_t> dims = dims_of(stored);
    const auto selection = selection_of(stored);
    if (stored == field.components)
      file.write("fields/" + name, dims, selection, field.values, field.unit);
    else
      file.write("fields/" + name, dims, selection, xdmf::padded_to_three_components(field.values),
                 field.unit);
  }
}

}  // namespace

class PartitionedFiles {
 public:
  PartitionedFiles(MPI_Comm comm, fs::path directory, std::string base_name)
      : directory_(std::move(directory)), base_name_(std::move(base_name)) {
    if (base_name_.empty() || base_name_.find('/') != std::string::npos)
      throw InputError("snapshot base name '" + base_name_ + "' is empty or contains '/'");
    MPI_Comm_dup(comm, &comm_);
    MPI_Comm_rank(comm_, &rank_);
    // Ranks that name different files would wait forever in MPI-IO's open
    // (Open MPI's OMPIO, when the open fails on some of them): all refuse now.
    const std::string where = (directory_ / base_name_).lexically_normal().string();
    unsigned long long name[2] = {std::hash<std::string>{}(where), 0};
    name[1] = ~name[0];
    MPI_Allreduce(MPI_IN_PLACE, name, 2, MPI_UNSIGNED_LONG_LONG, MPI_MAX, comm_);
    if (name[0] != ~name[1]) {
      MPI_Comm_free(&comm_);
      throw InputError(fmt::format(
          "partitioned snapshots '{}': the ranks name different files (this rank: '{}')",
          base_name_, where));
    }
    hdf5::silence_error_printing();
    if (rank_ == 0) create_output_directory(directory_);
    MPI_Barrier(comm_);
  }
  ~PartitionedFiles() {
    if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
  }
  PartitionedFiles(const PartitionedFiles&) = delete;
  PartitionedFiles& operator=(const PartitionedFiles&) = delete;

  std::size_t written() const { return written_; }
  fs::path index_path() const { return directory_ / (base_name_ + ".xdmf"); }
  fs::path snapshot_path(std::size_t step) const {
    return directory_ / fmt::format("{}_{:06}.h5", base_name_, step);
  }

  // The next snapshot at `time`: fill(file, transfer) adds its datasets to
  // the staged file, which every rank opens through MPI-IO; once all have
  // closed it, rank 0 renames it into place and adds grid(step, file name),
  // its <Grid>, to the index (collective).
  template <class Fill, class Grid>
  void write(double time, Fill&& fill, Grid&& grid) {
    hdf5::silence_error_printing();
    const std::size_t step = written_;
    const fs::path path = snapshot_path(step);
    const fs::path staged = staging_path(path);
    {
      const CollectiveIo io(comm_);
      hdf5::OutputFile file(staged, io.access.get());
      file.set_attribute("time", time);
      file.set_attribute("step", static_cast<std::int64_t>(step));
      fill(file, io.transfer.get());
      file.close();
    }
    MPI_Barrier(comm_);
    ++written_;
    if (rank_ != 0) return;
    commit_staged_file(staged, path);
    grids_.push_back(grid(step, path.filename().string()));
    xdmf::write_temporal_index(index_path(), base_name_, grids_);
  }

  const std::string& base_name() const { return base_name_; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  fs::path directory_;
  std::string base_name_;
  std::size_t written_ = 0;
  std::vector<std::string> grids_;  // rank 0: the <Grid> of every snapshot
};

PartitionedSnapshotWriter::PartitionedSnapshotWriter(
    MPI_Comm comm, fs::path directory, std::string base_name, Mesh mesh,
    const std::array<decomposition::Range, 3>& block)
    : mesh_(std::move(mesh)) {
  validate(mesh_);
  set_block(block);
  files_ = std::make_unique<PartitionedFiles>(comm, std::move(directory), std::move(base_name));
}

void PartitionedSnapshotWriter::set_block(const std::array<decomposition::Range, 3>& block) {
  const Index3 extent = split_grid(mesh_).extent();
  for (std::size_t d = 0; d < 3; ++d) {
    if (block[d].begin < 0 || block[d].end > extent[d] || block[d].size() < 1)
      throw InputError(
          fmt::format("partitioned snapshots of mesh '{}': a block [{}, {}) outside its {} "
                      "values in direction {}",
                      mesh_.name, block[d].begin, block[d].end, extent[d], d));
  }
  block_ = block;
}

PartitionedSnapshotWriter::~PartitionedSnapshotWriter() = default;

std::size_t PartitionedSnapshotWriter::snapshots_written() const {
  return files_->written();
}

fs::path PartitionedSnapshotWriter::index_path() const {
  return files_->index_path();
}

fs::path PartitionedSnapshotWriter::snapshot_path(std::size_t step) const {
  return files_->snapshot_path(step);
}

void PartitionedSnapshotWriter::write(double time, const SnapshotFields& fields) {
  const std::size_t cells = block_cells(block_);
  for (const auto& [name, field] : fields)
    if (field.components < 1 ||
        field.values.size() != cells * static_cast<std::size_t>(field.components))
      throw InputError(fmt::format(
          "partitioned snapshots '{}': field '{}' has {} values; the block has {} values x {} "
          "components",
          files_->base_name(), name, field.values.size(), cells, field.components));
  const int dim = split_grid(mesh_).dim;
  files_->write(
      time,
      [&](hdf5::OutputFile& file, hid_t transfer) {
        // dims are slowest first: (z,) y, x [, components]
        std::vector<hsize_t> start, count;
        for (int d = dim - 1; d >= 0; --d) {
          start.push_back(static_cast<hsize_t>(block_[static_cast<std::size_t>(d)].begin));
          count.push_back(static_cast<hsize_t>(block_[static_cast<std::size_t>(d)].size()));
        }
        const std::size_t spatial = start.size();
        write_fields(
            file, fields, [&](int stored) { return xdmf::field_dims(mesh_, stored); },
            [&, spatial](int stored) {
              start.resize(spatial);
              count.resize(spatial);
              if (stored > 1) {
                start.push_back(0);
                count.push_back(static_cast<hsize_t>(stored));
              }
              return hdf5::OutputFile::Part{start, count, transfer};
            });
      },
      [&](std::size_t step, const std::string& file) {
        return xdmf::snapshot_grid(files_->base_name(), step, time, mesh_, "", file, fields);
      });
}

PartitionedPointCloudWriter::PartitionedPointCloudWriter(MPI_Comm comm, fs::path directory,
                                                         std::string base_name,
                                                         std::string mesh_name, int dim,
                                                         std::size_t points)
    : mesh_name_(std::move(mesh_name)), dim_(dim), points_(points) {
  if (dim_ != 2 && dim_ != 3)
    throw InputError(
        fmt::format("partitioned snapshots of point cloud '{}': dimension {}", mesh_name_, dim_));
  files_ = std::make_unique<PartitionedFiles>(comm, std::move(directory), std::move(base_name));
}

PartitionedPointCloudWriter::~PartitionedPointCloudWriter() = default;

std::size_t PartitionedPointCloudWriter::snapshots_written() const {
  return files_->written();
}

fs::path PartitionedPointCloudWriter::index_path() const {
  return files_->index_path();
}

fs::path PartitionedPointCloudWriter::snapshot_path(std::size_t step) const {
  return files_->snapshot_path(step);
}

// The datasets of SnapshotWriter's snapshot of a moving point cloud, in its
// order: geometry/xyz (zero-padded to 3), topology/connectivity (the point
// itself), then the fields; each rank writes its rows.
void PartitionedPointCloudWriter::write(double time, std::span<const std::uint64_t> rows,
                                        std::span<const double> positions,
                                        const SnapshotFields& fields) {
  const std::size_t n = rows.size();
  const std::string& base_name = files_->base_name();
  if (positions.size() != n * static_cast<std::size_t>(dim_))
    throw InputError(fmt::format("partitioned snapshots '{}': {} positions for {} points",
                                 base_name, positions.size(), n));
  for (const auto& [name, field] : fields)
    if (field.components < 1 ||
        field.values.size() != n * static_cast<std::size_t>(field.components))
      throw InputError(fmt::format(
          "partitioned snapshots '{}': field '{}' has {} values; this rank has {} points x {} "
          "components",
          base_name, name, field.values.size(), n, field.components));
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
  const auto dim = static_cast<std::size_t>(dim_);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t d = 0; d < dim; ++d) xyz[3 * k + d] = positions[dim * k + d];
    connectivity[k] = static_cast<std::int64_t>(rows[k]);
  }
  files_->write(
      time,
      [&](hdf5::OutputFile& file, hid_t transfer) {
        const hdf5::OutputFile::Rows mine{runs, transfer};
        const hsize_t xyz_dims[] = {points_, 3};
        file.write("geometry/xyz", xyz_dims, mine, xyz, "m");
        const hsize_t point_dims[] = {points_};
        file.write("topology/connectivity", point_dims, mine, connectivity);
        write_fields(
            file, fields,
            [&](int stored) {
              std::vector<hsize_t> dims{points_};
              if (stored > 1) dims.push_back(static_cast<hsize_t>(stored));
              return dims;
            },
            [&](int) { return mine; });
      },
      [&](std::size_t step, const std::string& file) {
        // The XDMF text needs the cloud's size only.
        PointCloud sized;
        sized.dim = dim_;
        sized.volumes.assign(points_, 0.0);
        return xdmf::snapshot_grid(base_name, step, time, Mesh{mesh_name_, std::move(sized)}, file,
                                   file, fields);
      });
}

}  // namespace cosim
