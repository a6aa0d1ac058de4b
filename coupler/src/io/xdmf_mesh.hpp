#pragma once

#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cosim/io/snapshot_writer.hpp"
#include "cosim/mesh.hpp"

// How each mesh kind is represented in XDMF 3 and its HDF5 heavy data
// (the table in cosim/io/snapshot_writer.hpp).
namespace cosim::xdmf {

// Uniform 2D/3D grids have an implicit geometry (CoRectMesh); every other
// mesh stores node coordinates and connectivity.
bool has_explicit_geometry(const Mesh& mesh);

struct ExplicitGeometry {
  std::vector<double> xyz;                 // nodes x 3, zero-padded
  std::vector<std::int64_t> connectivity;  // elements x nodes_per_element
  hsize_t nodes = 0;
  hsize_t elements = 0;
  hsize_t nodes_per_element = 1;
};
ExplicitGeometry explicit_geometry(const Mesh& mesh);

// Components as stored: 2D vectors are padded to 3.
int stored_components(int components);
const char* attribute_type(int components);
const char* attribute_center(const Mesh& mesh);
// Dataset dims of a field, slowest first, with the component axis last when
// stored_components > 1.
std::vector<hsize_t> field_dims(const Mesh& mesh, int stored_components);

// <Topology> and <Geometry> elements; `geometry_file` names the HDF5 file
// holding /geometry/xyz and /topology/connectivity when the mesh needs them.
std::string topology_and_geometry(const Mesh& mesh, const std::string& geometry_file,
                                  std::string_view indent);

// The <Grid> element of snapshot `step` of `base_name` at `time`: the mesh
// and every field, read from /fields/<name> of `file`.
std::string snapshot_grid(std::string_view base_name, std::size_t step, double time,
                          const Mesh& mesh, const std::string& geometry_file,
                          const std::string& file, const SnapshotFields& fields);
// The temporal collection of `grids`, written to `path` atomically.
void write_temporal_index(const std::filesystem::path& path, std::string_view base_name,
                          const std::vector<std::string>& grids);
// 2D vectors with a zero third component, as ParaView needs them.
std::vector<double> padded_to_three_components(std::span<const double> values);

std::string dims_text(const std::vector<hsize_t>& dims);
std::string escape_xml(std::string_view text);

}  // namespace cosim::xdmf
