#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

namespace openfoam {

// The cells sharing a face with each cell (compressed rows).
class CellNeighbours {
 public:
  CellNeighbours() = default;

  // A generated case's grid (x fastest): the neighbours along x, y, z, the
  // lower before the upper.
  static CellNeighbours of_grid(const std::array<int, 3>& cells);

  // An OpenFOAM mesh: the owner and neighbour of each internal face
  // (constant/polyMesh/owner and neighbour, ASCII).
  static CellNeighbours of_mesh(const std::filesystem::path& poly_mesh, std::size_t cells);

  std::size_t size() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  std::span<const std::size_t> of(std::size_t cell) const {
    return {cells_.data() + offsets_[cell], offsets_[cell + 1] - offsets_[cell]};
  }

 private:
  std::vector<std::size_t> offsets_;
  std::vector<std::size_t> cells_;
};

}  // namespace openfoam
