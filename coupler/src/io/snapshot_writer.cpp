#include "cosim/io/snapshot_writer.hpp"

#include <fmt/format.h>

#include <utility>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "hdf5_file.hpp"
#include "xdmf_mesh.hpp"

namespace cosim {

namespace fs = std::filesystem;

namespace {

void write_geometry(hdf5::OutputFile& file, const Mesh& mesh) {
  const xdmf::ExplicitGeometry g = xdmf::explicit_geometry(mesh);
  const hsize_t xyz_dims[] = {g.nodes, 3};
  file.write("geometry/xyz", xyz_dims, g.xyz, "m");
  if (g.nodes_per_element == 1) {
    const hsize_t dims[] = {g.elements};
    file.write("topology/connectivity", dims, g.connectivity);
  } else {
    const hsize_t dims[] = {g.elements, g.nodes_per_element};
    file.write("topology/connectivity", dims, g.connectivity);
  }
}

// Stages `path`, runs `fill` on the new HDF5 file and renames it into place
// once closed, so `path` is either absent or complete.
template <class Fill>
void write_hdf5_atomically(const fs::path& path, Fill&& fill) {
  const fs::path staged = staging_path(path);
  try {
    hdf5::OutputFile file(staged);
    fill(file);
    file.close();
    commit_staged_file(staged, path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(staged, ignored);
    throw;
  }
}

}  // namespace

SnapshotWriter::SnapshotWriter(fs::path directory, std::string base_name, Mesh mesh)
    : directory_(std::move(directory)), base_name_(std::move(base_name)), mesh_(std::move(mesh)) {
  validate(mesh_);
  if (base_name_.empty() || base_name_.find('/') != std::string::npos)
    throw InputError("snapshot base name '" + base_name_ + "' is empty or contains '/'");
  hdf5::silence_error_printing();
  create_output_directory(directory_);
  if (xdmf::has_explicit_geometry(mesh_) && mesh_.kind() != MeshKind::point_cloud) {
    geometry_file_ = base_name_ + "_mesh.h5";
    write_hdf5_atomically(directory_ / geometry_file_,
                          [this](hdf5::OutputFile& file) { write_geometry(file, mesh_); });
  }
}

fs::path SnapshotWriter::index_path() const {
  return directory_ / (base_name_ + ".xdmf");
}

fs::path SnapshotWriter::snapshot_path(std::size_t step) const {
  return directory_ / fmt::format("{}_{:06}.h5", base_name_, step);
}

void SnapshotWriter::write(double time, const SnapshotFields& fields) {
  check_fields(mesh_, fields);
  write_snapshot(time, mesh_, fields, mesh_.kind() == MeshKind::point_cloud);
}

void SnapshotWriter::write(double time, const Mesh& current_mesh, const SnapshotFields& fields) {
  if (current_mesh.kind() != mesh_.kind())
    throw InputError(fmt::format("snapshots '{}': mesh '{}' changed kind from {} to {}", base_name_,
                                 mesh_.name, to_string(mesh_.kind()),
                                 to_string(current_mesh.kind())));
  if (xdmf::has_explicit_geometry(current_mesh) != xdmf::has_explicit_geometry(mesh_))
    throw InputError(
        fmt::format("snapshots '{}': mesh '{}' changed dimension", base_name_, mesh_.name));
  validate(current_mesh);
  check_fields(current_mesh, fields);
  write_snapshot(time, current_mesh, fields, xdmf::has_explicit_geometry(current_mesh));
  mesh_ = current_mesh;
}

void SnapshotWriter::check_fields(const Mesh& mesh, const SnapshotFields& fields) const {
  for (const auto& [name, field] : fields) {
    if (name.empty() || name == "." || name == ".." ||
        name.find_first_of("/:") != std::string::npos)
      throw InputError(
          fmt::format("snapshots '{}': field name '{}' is empty, '.', '..' or "
                      "contains '/' or ':'",
                      base_name_, name));
    if (field.components < 1)
      throw InputError(fmt::format("snapshots '{}': field '{}' has {} components", base_name_, name,
                                   field.components));
    const std::size_t expected = mesh.size() * static_cast<std::size_t>(field.components);
    if (field.values.size() != expected)
      throw InputError(fmt::format(
          "snapshots '{}': field '{}' has {} values; mesh '{}' has {} elements x {} components",
          base_name_, name, field.values.size(), mesh.name, mesh.size(), field.components));
  }
}

void SnapshotWriter::write_snapshot(double time, const Mesh& mesh, const SnapshotFields& fields,
                                    bool store_geometry) {
  hdf5::silence_error_printing();
  const std::size_t step = grids_.size();
  const fs::path path = snapshot_path(step);
  write_hdf5_atomically(path, [&](hdf5::OutputFile& file) {
    file.set_attribute("time", time);
    file.set_attribute("step", static_cast<std::int64_t>(step));
    if (store_geometry) write_geometry(file, mesh);
    for (const auto& [name, field] : fields) {
      const int stored = xdmf::stored_components(field.components);
      const std::vector<hsize_t> dims = xdmf::field_dims(mesh, stored);
      if (stored == field.components) {
        file.write("fields/" + name, dims, field.values, field.unit);
      } else {
        file.write("fields/" + name, dims, xdmf::padded_to_three_components(field.values),
                   field.unit);
      }
    }
  });
  if (store_geometry) geometry_file_ = path.filename().string();
  grids_.push_back(grid_xml(step, time, mesh, fields));
  rewrite_index();
}

std::string SnapshotWriter::grid_xml(std::size_t step, double time, const Mesh& mesh,
                                     const SnapshotFields& fields) const {
  return xdmf::snapshot_grid(base_name_, step, time, mesh, geometry_file_,
                             snapshot_path(step).filename().string(), fields);
}

void SnapshotWriter::rewrite_index() const {
  xdmf::write_temporal_index(index_path(), base_name_, grids_);
}

}  // namespace cosim
