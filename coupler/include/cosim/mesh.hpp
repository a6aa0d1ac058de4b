#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

// Mesh descriptors a participant declares to the coupler (architecture.md §5).
// Coordinates are SI metres; unused trailing dimensions are ignored.
namespace cosim {

using Vec3 = std::array<double, 3>;
using Index3 = std::array<std::int64_t, 3>;

// Where the values of a uniform grid live.
enum class GridLocation : std::uint8_t {
  cell,  // one value per cell, at its centre; control volume = the cell
  node,  // one value per node; control volume = the dual cell (halved at the boundary)
};

// Uniform Cartesian grid of `cells[d]` cells of size `spacing[d]` from
// `origin` in each of `dim` directions.
struct UniformGrid {
  int dim = 1;
  Vec3 origin{0, 0, 0};
  Vec3 spacing{1, 1, 1};
  Index3 cells{1, 1, 1};
  GridLocation location = GridLocation::cell;

  // Values per direction: cells[d] (cell-centred) or cells[d] + 1 (nodal).
  Index3 extent() const;
  std::size_t size() const;
  // Flat index of (i, j, k), x fastest.
  std::size_t flat(std::int64_t i, std::int64_t j = 0, std::int64_t k = 0) const;
  Index3 unflat(std::size_t flat_index) const;
  Vec3 position(std::size_t flat_index) const;
  double control_volume(std::size_t flat_index) const;
  Vec3 upper() const;  // origin + cells * spacing
};

// 1D line of cells with arbitrary edges x_0 < x_1 < ... < x_n: n cells.
struct NonUniformLine {
  std::vector<double> edges;

  std::size_t size() const { return edges.empty() ? 0 : edges.size() - 1; }
  double centre(std::size_t cell) const { return 0.5 * (edges[cell] + edges[cell + 1]); }
  double width(std::size_t cell) const { return edges[cell + 1] - edges[cell]; }
};

// Points with the volume each represents (material points): positions are
// stored point-major, `dim` coordinates per point.
struct PointCloud {
  int dim = 3;
  std::vector<double> positions;
  std::vector<double> volumes;

  std::size_t size() const { return volumes.size(); }
  Vec3 position(std::size_t p) const;
};

// Cells of an unstructured mesh reduced to their centres and volumes
// (OpenFOAM meshes): same layout as PointCloud.
struct CellCloud {
  int dim = 3;
  std::vector<double> centres;
  std::vector<double> volumes;

  std::size_t size() const { return volumes.size(); }
  Vec3 centre(std::size_t c) const;
};

using MeshGeometry = std::variant<UniformGrid, NonUniformLine, PointCloud, CellCloud>;

enum class MeshKind : std::uint8_t { uniform_grid, nonuniform_line, point_cloud, cell_cloud };

struct Mesh {
  std::string name;
  MeshGeometry geometry;

  MeshKind kind() const { return static_cast<MeshKind>(geometry.index()); }
  int dimension() const;
  std::size_t size() const;
  double control_volume(std::size_t element) const;
  Vec3 position(std::size_t element) const;
};

// The part of a mesh that one rank of a participant on several ranks holds
// (architecture.md §15): the whole mesh's indices of its elements, in the
// order of this rank's values. A grid is declared whole (every rank the same
// geometry) with the part it holds; a cloud by this rank's own elements.
// A grid's part may hold ghosts, elements another rank owns: the rank reads
// their values (the coupler sends every element held) but its writes of
// them are not sent. Every element is owned by one rank.
struct MeshPart {
  std::vector<std::int64_t> elements;
  std::vector<std::uint8_t> owned = {};  // per element, 0 for a ghost; empty: all owned

  std::size_t size() const { return elements.size(); }
  bool owns(std::size_t i) const { return owned.empty() || owned[i] != 0; }
  bool has_ghosts() const;
  // The values with indices lower <= (i, j, k) < upper of a grid (value
  // indices: cells, or nodes for a nodal grid), x fastest.
  static MeshPart box(const UniformGrid& grid, const Index3& lower, const Index3& upper);
  // The same box held, of which the rank owns owned_lower <= (i, j, k) < owned_upper.
  static MeshPart box(const UniformGrid& grid, const Index3& lower, const Index3& upper,
                      const Index3& owned_lower, const Index3& owned_upper);
};

const char* to_string(MeshKind kind);
const char* to_string(GridLocation location);

// Checks a mesh for the mistakes a solver author can make (non-positive
// spacing or volumes, unsorted edges, positions/volumes size mismatch, a
// dimension outside 1..3); throws InputError naming the mesh.
void validate(const Mesh& mesh);

}  // namespace cosim
