#include "swe/coupling/extended_free_surface.hpp"

#include <stdexcept>
#include <variant>

namespace swe {

std::vector<double> extended_free_surface(const Solver& solver, std::span<const double> dry_level) {
  if (solver.dimension() != 2)
    throw std::invalid_argument("extended_free_surface: the solver is not 2D");
  const auto h = solver.depth();
  const auto bed = solver.bed();
  if (dry_level.size() != h.size())
    throw std::invalid_argument("extended_free_surface: dry_level has the wrong size");
  const auto grid = std::get<cosim::UniformGrid>(solver.cells());
  const auto nx = static_cast<std::size_t>(grid.cells[0]);
  const auto ny = static_cast<std::size_t>(grid.cells[1]);
  const double dry = solver.physics().dry_depth;

  std::vector<double> eta(h.size(), 0.0);
  std::vector<char> reached(h.size(), 0);
  std::vector<std::size_t> ring;
  for (std::size_t c = 0; c < h.size(); ++c)
    if (h[c] > dry) {
      eta[c] = h[c] + bed[c];
      reached[c] = 1;
      ring.push_back(c);
    }
  if (ring.empty()) return {dry_level.begin(), dry_level.end()};

  // Breadth first from the water: a cell of the next ring takes the mean of
  // the neighbours reached before its ring, so the result does not depend on
  // the order within a ring.
  std::vector<std::size_t> next;
  std::vector<double> sum(h.size(), 0.0);
  std::vector<int> count(h.size(), 0);
  while (!ring.empty()) {
    next.clear();
    for (const std::size_t c : ring) {
      const std::size_t i = c % nx;
      const std::size_t j = c / nx;
      auto visit = [&](std::size_t n) {
        if (reached[n]) return;
        if (count[n] == 0) next.push_back(n);
        sum[n] += eta[c];
        ++count[n];
      };
      if (i > 0) visit(c - 1);
      if (i + 1 < nx) visit(c + 1);
      if (j > 0) visit(c - nx);
      if (j + 1 < ny) visit(c + nx);
    }
    for (const std::size_t n : next) {
      eta[n] = sum[n] / count[n];
      reached[n] = 1;
    }
    ring.swap(next);
  }
  return eta;
}

}  // namespace swe
