#include "cosim/decomposition/cartesian_decomposition.hpp"

#include <fmt/format.h>

#include <limits>

#include "cosim/error.hpp"

namespace cosim::decomposition {

Range even_range(std::int64_t count, int parts, int part) {
  const std::int64_t base = count / parts, extra = count % parts;
  const std::int64_t begin = part * base + std::min<std::int64_t>(part, extra);
  return {begin, begin + base + (part < extra ? 1 : 0)};
}

std::array<int, 3> process_grid(int ranks, std::span<const std::int64_t> cells) {
  const auto dim = static_cast<int>(cells.size());
  if (dim < 1 || dim > 3) throw InputError(fmt::format("a grid of {} directions", dim));
  if (ranks < 1) throw InputError(fmt::format("{} ranks: at least one is needed", ranks));
  std::array<std::int64_t, 3> n{1, 1, 1};
  for (int d = 0; d < dim; ++d) n[static_cast<std::size_t>(d)] = cells[static_cast<std::size_t>(d)];
  // The cells on the faces between parts: (dims[d] - 1) cuts across the
  // other directions' cells, in each direction.
  auto faces = [&](const std::array<int, 3>& dims) {
    std::int64_t total = 0;
    for (std::size_t d = 0; d < 3; ++d) total += (dims[d] - 1) * (n[0] * n[1] * n[2] / n[d]);
    return total;
  };
  std::array<int, 3> best{0, 0, 0};
  std::int64_t best_faces = std::numeric_limits<std::int64_t>::max();
  for (int a = 1; a <= ranks; ++a) {
    if (ranks % a != 0 || a > n[0]) continue;
    for (int b = 1; b <= ranks / a; ++b) {
      if ((ranks / a) % b != 0 || b > n[1]) continue;
      const int c = ranks / a / b;
      if (c > n[2]) continue;
      const std::array<int, 3> dims{a, b, c};
      const std::int64_t f = faces(dims);
      if (f < best_faces) {
        best_faces = f;
        best = dims;
      }
    }
  }
  if (best[0] == 0) {
    std::string shape = fmt::format("{}", n[0]);
    for (int d = 1; d < dim; ++d) shape += fmt::format(" x {}", n[static_cast<std::size_t>(d)]);
    throw InputError(fmt::format(
        "{} ranks do not fit a grid of {} cells: no split gives every rank a cell in each "
        "direction",
        ranks, shape));
  }
  return best;
}

CartesianDecomposition::CartesianDecomposition(int dim, std::array<std::int64_t, 3> cells,
                                               std::array<int, 3> dims)
    : dim_(dim), cells_(cells), dims_(dims) {
  if (dim < 1 || dim > 3) throw InputError(fmt::format("a grid of {} directions", dim));
  for (std::size_t d = 0; d < 3; ++d) {
    if (static_cast<int>(d) >= dim) {
      cells_[d] = 1;
      if (dims_[d] != 1)
        throw InputError(
            fmt::format("{} parts along direction {} of a {}D grid", dims_[d], d, dim));
    }
    if (cells_[d] < 1 || dims_[d] < 1)
      throw InputError(fmt::format("direction {}: {} cells in {} parts", d, cells_[d], dims_[d]));
    if (dims_[d] > cells_[d])
      throw InputError(fmt::format("direction {}: {} parts of {} cells leave a part without a cell",
                                   d, dims_[d], cells_[d]));
  }
}

int CartesianDecomposition::rank_of(const std::array<int, 3>& coords) const {
  return (coords[0] * dims_[1] + coords[1]) * dims_[2] + coords[2];
}

std::array<int, 3> CartesianDecomposition::coords_of(int rank) const {
  return {rank / (dims_[1] * dims_[2]), (rank / dims_[2]) % dims_[1], rank % dims_[2]};
}

Block CartesianDecomposition::block(int rank) const {
  if (rank < 0 || rank >= ranks())
    throw InputError(fmt::format("rank {} of a decomposition over {} ranks", rank, ranks()));
  Block b;
  b.coords = coords_of(rank);
  for (std::size_t d = 0; d < 3; ++d) {
    b.cells[d] = even_range(cells_[d], dims_[d], b.coords[d]);
    for (int side = 0; side < 2; ++side) {
      std::array<int, 3> across = b.coords;
      across[d] += side == 0 ? -1 : 1;
      if (across[d] >= 0 && across[d] < dims_[d])
        b.neighbour[2 * d + static_cast<std::size_t>(side)] = rank_of(across);
    }
  }
  return b;
}

int CartesianDecomposition::owner(const std::array<std::int64_t, 3>& cell) const {
  std::array<int, 3> coords{0, 0, 0};
  for (std::size_t d = 0; d < 3; ++d) {
    if (cell[d] < 0 || cell[d] >= cells_[d])
      throw InputError(fmt::format("cell {} along direction {} is outside the grid's {} cells",
                                   cell[d], d, cells_[d]));
    // The part of even_range holding the cell: the first `extra` parts are
    // one longer.
    const std::int64_t base = cells_[d] / dims_[d], extra = cells_[d] % dims_[d];
    const std::int64_t long_cells = extra * (base + 1);
    coords[d] = static_cast<int>(cell[d] < long_cells ? cell[d] / (base + 1)
                                                      : extra + (cell[d] - long_cells) / base);
  }
  return rank_of(coords);
}

}  // namespace cosim::decomposition
