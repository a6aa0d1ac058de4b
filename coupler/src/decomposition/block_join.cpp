#include "cosim/decomposition/block_join.hpp"

#include <algorithm>
#include <stdexcept>

namespace cosim::decomposition {

namespace {

using Index = std::array<std::int64_t, 3>;

// Whether the block stores the grid cell at `cell`, and where.
bool stored_at(const StoredBlock& b, const Index& cell, std::size_t& at) {
  std::size_t flat = 0, stride = 1;
  for (std::size_t d = 0; d < 3; ++d) {
    const std::int64_t local = cell[d] - b.stored[d].begin;
    if (local < 0 || local >= b.stored[d].size()) return false;
    flat += static_cast<std::size_t>(local) * stride;
    stride *= static_cast<std::size_t>(b.stored[d].size());
  }
  at = flat;
  return true;
}

bool owns(const StoredBlock& b, const Index& cell) {
  for (std::size_t d = 0; d < 3; ++d)
    if (cell[d] < b.owned[d].begin || cell[d] >= b.owned[d].end) return false;
  return true;
}

}  // namespace

StoredBlock StoredBlock::padded(const std::array<Range, 3>& owned, std::array<int, 3> ghosts,
                                int components) {
  StoredBlock b{owned, owned, components};
  for (std::size_t d = 0; d < 3; ++d)
    b.stored[d] = {owned[d].begin - ghosts[d], owned[d].end + ghosts[d]};
  return b;
}

std::size_t StoredBlock::size() const {
  return static_cast<std::size_t>(stored[0].size() * stored[1].size() * stored[2].size()) *
         static_cast<std::size_t>(components);
}

std::size_t join_blocks(std::span<const StoredBlock> from,
                        std::span<const std::span<const double>> values, const Index& grid_cells,
                        const StoredBlock& to, std::span<double> values_to) {
  if (values.size() != from.size() || values_to.size() != to.size())
    throw std::logic_error("join_blocks: arrays and blocks do not match");
  for (std::size_t p = 0; p < from.size(); ++p)
    if (values[p].size() != from[p].size() || from[p].components != to.components)
      throw std::logic_error("join_blocks: an array of another size than its block");
  const auto c = static_cast<std::size_t>(to.components);
  std::size_t missing = 0, out = 0;
  Index cell{};
  for (cell[2] = to.stored[2].begin; cell[2] < to.stored[2].end; ++cell[2])
    for (cell[1] = to.stored[1].begin; cell[1] < to.stored[1].end; ++cell[1])
      for (cell[0] = to.stored[0].begin; cell[0] < to.stored[0].end; ++cell[0], out += c) {
        bool inside = true;
        for (std::size_t d = 0; d < 3; ++d)
          inside = inside && cell[d] >= 0 && cell[d] < grid_cells[d];
        bool found = false;
        for (std::size_t p = 0; p < from.size() && !found; ++p) {
          std::size_t at = 0;
          if ((!inside || owns(from[p], cell)) && stored_at(from[p], cell, at)) {
            std::copy_n(values[p].begin() + static_cast<std::ptrdiff_t>(at * c), c,
                        values_to.begin() + static_cast<std::ptrdiff_t>(out));
            found = true;
          }
        }
        if (!found) ++missing;
      }
  return missing;
}

}  // namespace cosim::decomposition
