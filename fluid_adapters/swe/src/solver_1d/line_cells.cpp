#include "solver_1d/line_cells.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/error.hpp"

namespace swe::solver_1d {

LineCells make_line_cells(const std::vector<double>& edges) {
  if (edges.size() < 2) {
    throw cosim::InputError(
        fmt::format("Solver1d needs at least one cell (two edges), got {} edge(s)", edges.size()));
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!std::isfinite(edges[i])) {
      throw cosim::InputError(fmt::format("Solver1d: edge {} is not finite ({})", i, edges[i]));
    }
    if (i > 0 && !(edges[i] > edges[i - 1])) {
      throw cosim::InputError(fmt::format(
          "Solver1d: edges must increase, but edges[{}] = {} is not above edges[{}] = {}", i,
          edges[i], i - 1, edges[i - 1]));
    }
  }
  LineCells cells;
  const std::size_t n = edges.size() - 1;
  cells.count = n;
  std::vector<double> width(n + 2 * ghost_layers);
  for (std::size_t i = 0; i < n; ++i) width[i + ghost_layers] = edges[i + 1] - edges[i];
  width[1] = width[2];
  width[0] = width[std::min<std::size_t>(3, n + 1)];
  width[n + 2] = width[n + 1];
  width[n + 3] = width[n >= 2 ? n : n + 1];

  cells.half_width.resize(width.size());
  cells.inv_width.resize(width.size());
  for (std::size_t k = 0; k < width.size(); ++k) {
    cells.half_width[k] = 0.5 * width[k];
    cells.inv_width[k] = 1.0 / width[k];
  }
  cells.inv_centre_distance.resize(width.size() - 1);
  for (std::size_t k = 0; k + 1 < width.size(); ++k) {
    cells.inv_centre_distance[k] = 2.0 / (width[k] + width[k + 1]);
  }
  cells.inv_face_width.resize(n + 1);
  for (std::size_t f = 0; f <= n; ++f) {
    cells.inv_face_width[f] = 1.0 / std::min(width[f + 1], width[f + 2]);
  }
  return cells;
}

}  // namespace swe::solver_1d
