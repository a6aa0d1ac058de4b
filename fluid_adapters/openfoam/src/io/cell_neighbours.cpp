#include "openfoam/io/cell_neighbours.hpp"

#include <fmt/format.h>

#include "cosim/error.hpp"
#include "openfoam/foam/field_file.hpp"

namespace openfoam {

CellNeighbours CellNeighbours::of_grid(const std::array<int, 3>& n) {
  CellNeighbours result;
  const std::size_t cells = static_cast<std::size_t>(n[0]) * n[1] * n[2];
  result.offsets_.reserve(cells + 1);
  result.offsets_.push_back(0);
  const long step[3] = {1, n[0], static_cast<long>(n[0]) * n[1]};
  for (std::size_t c = 0; c < cells; ++c) {
    const long at[3] = {static_cast<long>(c) % n[0], (static_cast<long>(c) / n[0]) % n[1],
                        static_cast<long>(c) / step[2]};
    for (int d = 0; d < 3; ++d) {
      for (int side : {-1, 1}) {
        const long next = at[d] + side;
        if (next < 0 || next >= n[d]) continue;
        result.cells_.push_back(static_cast<std::size_t>(static_cast<long>(c) + side * step[d]));
      }
    }
    result.offsets_.push_back(result.cells_.size());
  }
  return result;
}

CellNeighbours CellNeighbours::of_mesh(const std::filesystem::path& poly_mesh, std::size_t cells) {
  const std::vector<std::int64_t> owner = read_label_list(poly_mesh / "owner");
  const std::vector<std::int64_t> neighbour = read_label_list(poly_mesh / "neighbour");
  if (neighbour.size() > owner.size()) {
    throw cosim::Error(
        cosim::ExitCode::participant_failed,
        fmt::format("{}: {} internal faces but only {} faces in owner",
                    (poly_mesh / "neighbour").string(), neighbour.size(), owner.size()));
  }
  std::vector<std::size_t> count(cells + 1, 0);
  const auto cell_of = [&](std::int64_t label, const char* file) {
    if (label < 0 || static_cast<std::size_t>(label) >= cells) {
      throw cosim::Error(cosim::ExitCode::participant_failed,
                         fmt::format("{}: cell label {} outside the mesh's {} cells",
                                     (poly_mesh / file).string(), label, cells));
    }
    return static_cast<std::size_t>(label);
  };
  for (std::size_t f = 0; f < neighbour.size(); ++f) {
    ++count[cell_of(owner[f], "owner") + 1];
    ++count[cell_of(neighbour[f], "neighbour") + 1];
  }
  CellNeighbours result;
  result.offsets_.assign(cells + 1, 0);
  for (std::size_t c = 0; c < cells; ++c)
    result.offsets_[c + 1] = result.offsets_[c] + count[c + 1];
  result.cells_.resize(result.offsets_.back());
  std::vector<std::size_t> fill(result.offsets_.begin(), result.offsets_.end() - 1);
  for (std::size_t f = 0; f < neighbour.size(); ++f) {
    const auto a = static_cast<std::size_t>(owner[f]);
    const auto b = static_cast<std::size_t>(neighbour[f]);
    result.cells_[fill[a]++] = b;
    result.cells_[fill[b]++] = a;
  }
  return result;
}

}  // namespace openfoam
