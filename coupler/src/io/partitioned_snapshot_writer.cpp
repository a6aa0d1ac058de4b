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
    throw InputError(
        fmt::format("partitioned snapshots '{}': the ranks name different files (this rank: '{}')",
                    base_name_, where));
  }
  hdf5::silence_error_printing();
  if (rank_ == 0) create_output_directory(directory_);
  MPI_Barrier(comm_);
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
    const hdf5::PropertyListHandle access(H5Pcreate(H5P_FILE_ACCESS), "file access properties");
    if (H5Pset_fapl_mpio(access.get(), comm_, MPI_INFO_NULL) < 0) hdf5::fail("MPI-IO file access");
    const hdf5::PropertyListHandle transfer(H5Pcreate(H5P_DATASET_XFER), "transfer properties");
    if (H5Pset_dxpl_mpio(transfer.get(), H5FD_MPIO_COLLECTIVE) < 0)
      hdf5::fail("collective transfers");
    hdf5::OutputFile file(staged, access.get());
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
      const hdf5::OutputFile::Part part{start, count, transfer.get()};
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

}  // namespace cosim
