#include "xdmf_mesh.hpp"

#include <fmt/format.h>

#include "cosim/io/files.hpp"

namespace cosim::xdmf {

namespace {

std::size_t line_cells(const Mesh& mesh) {
  if (const auto* grid = std::get_if<UniformGrid>(&mesh.geometry))
    return static_cast<std::size_t>(grid->cells[0]);
  return std::get<NonUniformLine>(mesh.geometry).size();
}

std::vector<double> line_nodes_x(const Mesh& mesh) {
  if (const auto* grid = std::get_if<UniformGrid>(&mesh.geometry)) {
    std::vector<double> x(static_cast<std::size_t>(grid->cells[0]) + 1);
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = grid->origin[0] + static_cast<double>(i) * grid->spacing[0];
    return x;
  }
  return std::get<NonUniformLine>(mesh.geometry).edges;
}

bool is_line(const Mesh& mesh) {
  return mesh.kind() == MeshKind::nonuniform_line ||
         (mesh.kind() == MeshKind::uniform_grid && mesh.dimension() == 1);
}

std::string xml_triplet(const Vec3& v, int dim) {
  std::string text;
  for (int d = dim - 1; d >= 0; --d)
    text += fmt::format("{}{:.17g}", d == dim - 1 ? "" : " ", v[d]);
  return text;
}

}  // namespace

bool has_explicit_geometry(const Mesh& mesh) {
  return !(mesh.kind() == MeshKind::uniform_grid && mesh.dimension() >= 2);
}

ExplicitGeometry explicit_geometry(const Mesh& mesh) {
  ExplicitGeometry g;
  if (is_line(mesh)) {
    const std::vector<double> x = line_nodes_x(mesh);
    g.nodes = x.size();
    g.elements = line_cells(mesh);
    g.nodes_per_element = 2;
    g.xyz.assign(3 * x.size(), 0.0);
    for (std::size_t n = 0; n < x.size(); ++n) g.xyz[3 * n] = x[n];
    g.connectivity.resize(2 * g.elements);
    for (std::size_t e = 0; e < g.elements; ++e) {
      g.connectivity[2 * e] = static_cast<std::int64_t>(e);
      g.connectivity[2 * e + 1] = static_cast<std::int64_t>(e + 1);
    }
    return g;
  }
  g.nodes = g.elements = mesh.size();
  g.nodes_per_element = 1;
  g.xyz.resize(3 * mesh.size());
  g.connectivity.resize(mesh.size());
  for (std::size_t p = 0; p < mesh.size(); ++p) {
    const Vec3 x = mesh.position(p);
    for (int d = 0; d < 3; ++d) g.xyz[3 * p + d] = x[d];
    g.connectivity[p] = static_cast<std::int64_t>(p);
  }
  return g;
}

int stored_components(int components) {
  return components == 2 ? 3 : components;
}

const char* attribute_type(int components) {
  switch (components) {
    case 1:
      return "Scalar";
    case 2:
    case 3:
      return "Vector";
    case 6:
      return "Tensor6";
    case 9:
      return "Tensor";
    default:
      return "Matrix";
  }
}

const char* attribute_center(const Mesh& mesh) {
  switch (mesh.kind()) {
    case MeshKind::uniform_grid:
      return std::get<UniformGrid>(mesh.geometry).location == GridLocation::cell ? "Cell" : "Node";
    case MeshKind::nonuniform_line:
      return "Cell";
    case MeshKind::point_cloud:
    case MeshKind::cell_cloud:
      return "Node";
  }
  return "Node";
}

std::vector<hsize_t> field_dims(const Mesh& mesh, int components) {
  std::vector<hsize_t> dims;
  if (const auto* grid = std::get_if<UniformGrid>(&mesh.geometry); grid && grid->dim >= 2) {
    const Index3 n = grid->extent();
    for (int d = grid->dim - 1; d >= 0; --d) dims.push_back(static_cast<hsize_t>(n[d]));
  } else {
    dims.push_back(mesh.size());
  }
  if (components > 1) dims.push_back(static_cast<hsize_t>(components));
  return dims;
}

std::string topology_and_geometry(const Mesh& mesh, const std::string& geometry_file,
                                  std::string_view indent) {
  if (const auto* grid = std::get_if<UniformGrid>(&mesh.geometry); grid && grid->dim >= 2) {
    std::vector<hsize_t> nodes;
    for (int d = grid->dim - 1; d >= 0; --d)
      nodes.push_back(static_cast<hsize_t>(grid->cells[d] + 1));
    const bool three_d = grid->dim == 3;
    const auto vector_item = [&](const Vec3& v) {
      return fmt::format(
          "{0}  <DataItem Format=\"XML\" Dimensions=\"{1}\" NumberType=\"Float\" "
          "Precision=\"8\">{2}</DataItem>\n",
          indent, grid->dim, xml_triplet(v, grid->dim));
    };
    return fmt::format(
        "{0}<Topology TopologyType=\"{1}\" Dimensions=\"{2}\"/>\n"
        "{0}<Geometry GeometryType=\"{3}\">\n{4}{5}{0}</Geometry>\n",
        indent, three_d ? "3DCoRectMesh" : "2DCoRectMesh", dims_text(nodes),
        three_d ? "ORIGIN_DXDYDZ" : "ORIGIN_DXDY", vector_item(grid->origin),
        vector_item(grid->spacing));
  }
  const bool line = is_line(mesh);
  const hsize_t nodes = line ? line_cells(mesh) + 1 : mesh.size();
  const hsize_t elements = line ? line_cells(mesh) : mesh.size();
  const std::string file = escape_xml(geometry_file);
  return fmt::format(
      "{0}<Topology TopologyType=\"{1}\" NodesPerElement=\"{2}\" NumberOfElements=\"{3}\">\n"
      "{0}  <DataItem Format=\"HDF\" Dimensions=\"{4}\" NumberType=\"Int\" "
      "Precision=\"8\">{5}:/topology/connectivity</DataItem>\n"
      "{0}</Topology>\n"
      "{0}<Geometry GeometryType=\"XYZ\">\n"
      "{0}  <DataItem Format=\"HDF\" Dimensions=\"{6} 3\" NumberType=\"Float\" "
      "Precision=\"8\">{5}:/geometry/xyz</DataItem>\n"
      "{0}</Geometry>\n",
      indent, line ? "Polyline" : "Polyvertex", line ? 2 : 1, elements,
      line ? fmt::format("{} 2", elements) : fmt::format("{}", elements), file, nodes);
}

std::string dims_text(const std::vector<hsize_t>& dims) {
  return fmt::format("{}", fmt::join(dims, " "));
}

std::string escape_xml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string snapshot_grid(std::string_view base_name, std::size_t step, double time,
                          const Mesh& mesh, const std::string& geometry_file,
                          const std::string& file, const SnapshotFields& fields) {
  const std::string escaped_file = escape_xml(file);
  std::string xml = fmt::format(
      "      <Grid Name=\"{}_{:06}\" GridType=\"Uniform\">\n"
      "        <Time Value=\"{:.17g}\"/>\n",
      escape_xml(base_name), step, time);
  xml += topology_and_geometry(mesh, geometry_file, "        ");
  for (const auto& [name, field] : fields) {
    const int stored = stored_components(field.components);
    xml += fmt::format(
        "        <Attribute Name=\"{0}\" AttributeType=\"{1}\" Center=\"{2}\">\n"
        "          <DataItem Format=\"HDF\" Dimensions=\"{3}\" NumberType=\"Float\" "
        "Precision=\"8\">{4}:/fields/{0}</DataItem>\n"
        "        </Attribute>\n",
        escape_xml(name), attribute_type(field.components), attribute_center(mesh),
        dims_text(field_dims(mesh, stored)), escaped_file);
  }
  xml += "      </Grid>\n";
  return xml;
}

void write_temporal_index(const std::filesystem::path& path, std::string_view base_name,
                          const std::vector<std::string>& grids) {
  std::string xml = fmt::format(
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<Xdmf Version=\"3.0\">\n"
      "  <Domain>\n"
      "    <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
      escape_xml(base_name));
  for (const std::string& grid : grids) xml += grid;
  xml += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  write_file_atomically(path, xml);
}

std::vector<double> padded_to_three_components(std::span<const double> values) {
  std::vector<double> padded(values.size() / 2 * 3, 0.0);
  for (std::size_t e = 0; e < values.size() / 2; ++e) {
    padded[3 * e] = values[2 * e];
    padded[3 * e + 1] = values[2 * e + 1];
  }
  return padded;
}

}  // namespace cosim::xdmf
