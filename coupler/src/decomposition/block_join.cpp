#include "cosim/decomposition/block_join.hpp"

#include <stdexcept>

namespace cosim::decomposition {

namespace {

using Index = std::array<std::int64_t, 3>;

// The stored extent of a block per direction: its cells and both ghost layers.
Index extent(const StoredBlock& b) {
  Index n{};
  for (std::size_t d = 0; d < 3; ++d) n[d] = b.cells[d].size() + 2 * b.ghosts[d];
  return n;
}

// Whether the block stores the grid cell at `cell` (owned or ghost), and where.
bool stored_at(const StoredBlock& b, const Index& cell, std::size_t& at) {
  const Index n = extent(b);
  std::size_t flat = 0, stride = 1;
  for (std::size_t d = 0; d < 3; ++d) {
    const std::int64_t local = cell[d] - b.cells[d].begin + b.ghosts[d];
    if (local < 0 || local >= n[d]) return false;
    flat += static_cast<std::size_t>(local) * stride;
    stride *= static_cast<std::size_t>(n[d]);
  }
  at = flat;
  return true;
}

bool owns(const StoredBlock& b, const Index& cell) {
  for (std::size_t d = 0; d < 3; ++d)
    if (cell[d] < b.cells[d].begin || cell[d] >= b.cells[d].end) return false;
  return true;
}

}  // namespace

std::size_t StoredBlock::size() const {
  const Index n = extent(*this);
  return static_cast<std::size_t>(n[0] * n[1] * n[2]);
}

std::size_t join_blocks(std::span<const StoredBlock> from,
                        std::span<const std::span<const double>> values, const Index& grid_cells,
                        const StoredBlock& to, std::span<double> values_to) {
  if (values.size() != from.size() || values_to.size() != to.size())
    throw std::logic_error("join_blocks: arrays and blocks do not match");
  for (std::size_t p = 0; p < from.size(); ++p)
    if (values[p].size() != from[p].size())
      throw std::logic_error("join_blocks: an array of another size than its block");
  const Index n = extent(to);
  std::size_t missing = 0, out = 0;
  Index cell{};
  for (std::int64_t k = 0; k < n[2]; ++k)
    for (std::int64_t j = 0; j < n[1]; ++j)
      for (std::int64_t i = 0; i < n[0]; ++i, ++out) {
        const Index local{i, j, k};
        bool inside = true;
        for (std::size_t d = 0; d < 3; ++d) {
          cell[d] = to.cells[d].begin - to.ghosts[d] + local[d];
          inside = inside && cell[d] >= 0 && cell[d] < grid_cells[d];
        }
        bool found = false;
        for (std::size_t p = 0; p < from.size() && !found; ++p) {
          std::size_t at = 0;
          if ((inside ? owns(from[p], cell) : true) && stored_at(from[p], cell, at)) {
            values_to[out] = values[p][at];
            found = true;
          }
        }
        if (!found) ++missing;
      }
  return missing;
}

}  // namespace cosim::decomposition
