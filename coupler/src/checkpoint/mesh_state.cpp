#include "checkpoint/mesh_state.hpp"

#include <fmt/format.h>

#include <type_traits>

#include "cosim/error.hpp"

namespace cosim::checkpoint {

void write_mesh(StateFileWriter& out, const std::string& key, const Mesh& mesh) {
  out.integer(key + ".kind", static_cast<std::int64_t>(mesh.kind()));
  std::visit(
      [&](const auto& g) {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, UniformGrid>) {
          out.integer(key + ".dim", g.dim);
          out.numbers(key + ".origin", g.origin);
          out.numbers(key + ".spacing", g.spacing);
          out.integers(key + ".cells", g.cells);
          out.integer(key + ".location", static_cast<std::int64_t>(g.location));
        } else if constexpr (std::is_same_v<G, NonUniformLine>) {
          out.numbers(key + ".edges", g.edges);
        } else if constexpr (std::is_same_v<G, PointCloud>) {
          out.integer(key + ".dim", g.dim);
          out.numbers(key + ".positions", g.positions);
          out.numbers(key + ".volumes", g.volumes);
        } else {
          out.integer(key + ".dim", g.dim);
          out.numbers(key + ".centres", g.centres);
          out.numbers(key + ".volumes", g.volumes);
        }
      },
      mesh.geometry);
}

Mesh read_mesh(const StateFileReader& in, const std::string& key, const std::string& name) {
  const auto kind = static_cast<MeshKind>(in.integer(key + ".kind"));
  Mesh mesh{name, UniformGrid{}};
  switch (kind) {
    case MeshKind::uniform_grid: {
      UniformGrid g;
      g.dim = static_cast<int>(in.integer(key + ".dim"));
      std::vector<double> v;
      in.numbers(key + ".origin", 3, v);
      std::copy(v.begin(), v.end(), g.origin.begin());
      in.numbers(key + ".spacing", 3, v);
      std::copy(v.begin(), v.end(), g.spacing.begin());
      std::vector<std::int64_t> cells;
      in.integers(key + ".cells", 3, cells);
      std::copy(cells.begin(), cells.end(), g.cells.begin());
      g.location = static_cast<GridLocation>(in.integer(key + ".location"));
      mesh.geometry = g;
      break;
    }
    case MeshKind::nonuniform_line:
      mesh.geometry = NonUniformLine{in.numbers(key + ".edges")};
      break;
    case MeshKind::point_cloud:
      mesh.geometry = PointCloud{static_cast<int>(in.integer(key + ".dim")),
                                 in.numbers(key + ".positions"), in.numbers(key + ".volumes")};
      break;
    case MeshKind::cell_cloud:
      mesh.geometry = CellCloud{static_cast<int>(in.integer(key + ".dim")),
                                in.numbers(key + ".centres"), in.numbers(key + ".volumes")};
      break;
    default:
      throw Error(ExitCode::bad_input,
                  fmt::format("{}: mesh '{}' is of an unknown kind", in.file().string(), name));
  }
  try {
    validate(mesh);
  } catch (const std::exception& e) {
    throw Error(ExitCode::bad_input, fmt::format("{}: mesh '{}' is not a valid mesh: {}",
                                                 in.file().string(), name, e.what()));
  }
  return mesh;
}

}  // namespace cosim::checkpoint
