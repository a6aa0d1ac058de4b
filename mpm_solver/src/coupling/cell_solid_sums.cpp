#include "mpm/coupling/cell_solid_sums.hpp"

#include <algorithm>
#include <array>

namespace mpm::coupling {

namespace {

// Sweeps over the grid: a cluster hands its excess on by at most this many cells.
constexpr int spreading_sweeps = 4;
// Relative overfill a cell keeps: round-off, and the overlap of axis-aligned (cpGIMP) domains of
// sheared points, whose area follows |F_xx F_yy| rather than J.
constexpr double overfill_tolerance = 1e-3;

}  // namespace

CellSolidSums::CellSolidSums(std::size_t cells, int dim)
    : domain(cells, 0.0),
      solid_volume(cells, 0.0),
      mass(cells, 0.0),
      momentum(cells * static_cast<std::size_t>(dim), 0.0),
      volume_momentum(cells * static_cast<std::size_t>(dim), 0.0),
      porous_mass(cells, 0.0),
      permeability_mass(cells, 0.0),
      grain_size_mass(cells, 0.0),
      dim_(static_cast<std::size_t>(dim)) {}

void CellSolidSums::move(std::size_t from, std::size_t to, double fraction) {
  auto shift = [&](std::vector<double>& v, std::size_t i, std::size_t j) {
    const double amount = fraction * v[i];
    v[i] -= amount;
    v[j] += amount;
  };
  for (auto* v :
       {&domain, &solid_volume, &mass, &porous_mass, &permeability_mass, &grain_size_mass})
    shift(*v, from, to);
  for (std::size_t k = 0; k < dim_; ++k) {
    shift(momentum, from * dim_ + k, to * dim_ + k);
    shift(volume_momentum, from * dim_ + k, to * dim_ + k);
  }
}

void sum_cells_over_ranks(CellSolidSums& free, CellSolidSums& held, const SumOverRanks& sum) {
  std::vector<double> packed;
  for (CellSolidSums* sums : {&free, &held})
    sums->for_each_array(
        [&](const std::vector<double>& v) { packed.insert(packed.end(), v.begin(), v.end()); });
  sum(packed);
  auto next = packed.begin();
  for (CellSolidSums* sums : {&free, &held})
    sums->for_each_array([&](std::vector<double>& v) {
      std::copy(next, next + static_cast<std::ptrdiff_t>(v.size()), v.begin());
      next += static_cast<std::ptrdiff_t>(v.size());
    });
}

template <int Dim>
std::size_t spread_overfilled_cells(const ExchangeGrid<Dim>& grid, CellSolidSums& free,
                                    const CellSolidSums& held) {
  const std::size_t cells = grid.size();
  const double cell_volume = grid.cell_volume();
  auto room = [&](std::size_t c) { return cell_volume - free.domain[c] - held.domain[c]; };
  std::size_t overfilled = 0;
  for (std::size_t c = 0; c < cells; ++c)
    if (free.domain[c] > 0.0 && room(c) < -overfill_tolerance * cell_volume) ++overfilled;
  if (overfilled == 0) return 0;

  for (int sweep = 0; sweep < spreading_sweeps; ++sweep) {
    bool moved = false;
    for (std::size_t c = 0; c < cells; ++c) {
      // Only the overfill beyond the tolerance, and the neighbours' room in
      // the proportion their own points fill them: what moves grows from 0
      // as a cell starts to overfill or a neighbour to be reached, so the
      // fields stay continuous in time (a compressible pore fluid turns a
      // jump of phi_s into one of pressure).
      const double excess = std::min(free.domain[c], -room(c) - overfill_tolerance * cell_volume);
      if (!(free.domain[c] > 0.0) || excess <= 0.0) continue;
      std::array<std::size_t, 2 * Dim> neighbour{};
      std::array<double, 2 * Dim> capacity{};
      std::size_t count = 0;
      double total_capacity = 0.0;
      grid.for_each_face_neighbour(c, [&](std::size_t b) {
        const double filled = std::min(1.0, free.domain[b] / cell_volume);
        const double accepts = std::max(0.0, room(b)) * filled;
        if (!(accepts > 0.0)) return;
        neighbour[count] = b;
        capacity[count++] = accepts;
        total_capacity += accepts;
      });
      if (count == 0) continue;
      const double given = std::min(excess, total_capacity);
      const double fraction_of_cell = given / free.domain[c];
      // Each neighbour takes its share of the cell's free sums as they stand
      // before any of them is moved.
      double left = 1.0;
      for (std::size_t k = 0; k < count; ++k) {
        const double share = fraction_of_cell * capacity[k] / total_capacity;
        free.move(c, neighbour[k], share / left);
        left -= share;
      }
      moved = true;
    }
    if (!moved) break;
  }
  return overfilled;
}

template std::size_t spread_overfilled_cells<2>(const ExchangeGrid<2>&, CellSolidSums&,
                                                const CellSolidSums&);
template std::size_t spread_overfilled_cells<3>(const ExchangeGrid<3>&, CellSolidSums&,
                                                const CellSolidSums&);

}  // namespace mpm::coupling
