#include "mpm/depth_averaged/cell_deposit.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>

namespace mpm {

cosim::UniformGrid ground_cells(const GridGeometry<2>& grid) {
  cosim::UniformGrid cells;
  cells.dim = 2;
  cells.origin = {grid.origin[0], grid.origin[1], 0.0};
  cells.spacing = {grid.spacing[0], grid.spacing[1], 1.0};
  cells.cells = {grid.cells[0], grid.cells[1], 1};
  cells.location = cosim::GridLocation::cell;
  return cells;
}

CellDeposit::CellDeposit(cosim::UniformGrid cells) : cells_(cells) {
  if (cells_.dim != 2 || cells_.location != cosim::GridLocation::cell || cells_.cells[0] < 2 ||
      cells_.cells[1] < 2)
    throw std::invalid_argument("CellDeposit: a 2D cell-centred grid of at least 2 x 2 cells");
}

std::vector<double> CellDeposit::deposit(std::span<const Vec<2>> positions,
                                         std::span<const double> values,
                                         std::size_t components) const {
  if (values.size() != positions.size() * components)
    throw std::invalid_argument("CellDeposit::deposit: values do not match the points");
  std::vector<double> cells(cells_.size() * components, 0.0);
  for (std::size_t p = 0; p < positions.size(); ++p)
    for_each_share(positions[p], [&](std::size_t c, double share) {
      for (std::size_t k = 0; k < components; ++k)
        cells[c * components + k] += share * values[p * components + k];
    });
  return cells;
}

std::vector<double> CellDeposit::distribute(std::span<const Vec<2>> positions,
                                            std::span<const double> weights,
                                            std::span<const double> amounts, std::size_t components,
                                            std::vector<double>* unplaced) const {
  const std::size_t n = cells_.size();
  if (weights.size() != positions.size() || amounts.size() != n * components)
    throw std::invalid_argument("CellDeposit::distribute: sizes do not match");
  std::vector<double> weight(n, 0.0);
  for (std::size_t p = 0; p < positions.size(); ++p)
    for_each_share(positions[p],
                   [&](std::size_t c, double share) { weight[c] += share * weights[p]; });

  std::vector<double> placed(amounts.begin(), amounts.end());
  if (unplaced) unplaced->assign(components, 0.0);
  const auto nx = static_cast<std::int64_t>(cells_.cells[0]);
  const auto ny = static_cast<std::int64_t>(cells_.cells[1]);
  for (std::size_t c = 0; c < n; ++c) {
    if (weight[c] > 0.0) continue;
    bool any = false;
    for (std::size_t k = 0; k < components; ++k) any = any || amounts[c * components + k] != 0.0;
    if (!any) continue;
    const auto ci = static_cast<std::int64_t>(c) % nx, cj = static_cast<std::int64_t>(c) / nx;
    bool found = false;
    for (std::int64_t r = 1; r < std::max(nx, ny) && !found; ++r) {
      double ring_weight = 0.0;
      auto ring = [&](auto&& f) {
        for (std::int64_t j = std::max<std::int64_t>(0, cj - r); j <= std::min(ny - 1, cj + r); ++j)
          for (std::int64_t i = std::max<std::int64_t>(0, ci - r); i <= std::min(nx - 1, ci + r);
               ++i)
            if (std::max(std::abs(i - ci), std::abs(j - cj)) == r)
              f(static_cast<std::size_t>(j * nx + i));
      };
      ring([&](std::size_t d) { ring_weight += weight[d]; });
      if (!(ring_weight > 0.0)) continue;
      found = true;
      ring([&](std::size_t d) {
        for (std::size_t k = 0; k < components; ++k)
          placed[d * components + k] += amounts[c * components + k] * weight[d] / ring_weight;
      });
    }
    for (std::size_t k = 0; k < components; ++k) {
      if (!found && unplaced) (*unplaced)[k] += amounts[c * components + k];
      placed[c * components + k] = 0.0;
    }
  }

  std::vector<double> points(positions.size() * components, 0.0);
  for (std::size_t p = 0; p < positions.size(); ++p)
    for_each_share(positions[p], [&](std::size_t c, double share) {
      if (!(weight[c] > 0.0)) return;
      const double fraction = share * weights[p] / weight[c];
      for (std::size_t k = 0; k < components; ++k)
        points[p * components + k] += fraction * placed[c * components + k];
    });
  return points;
}

}  // namespace mpm
