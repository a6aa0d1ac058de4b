#pragma once

#include <cstddef>
#include <vector>

#include "mpm/coupling/exchange_grid.hpp"
#include "mpm/coupling/over_ranks.hpp"

namespace mpm::coupling {

// What a set of particles puts in each exchange cell (porous_fields_writer),
// as sums over the particles with their conservative weights w_pc, before
// any division by the cell volume.
struct CellSolidSums {
  std::vector<double> domain;             // sum w V_p: the cell volume the points' domains cover
  std::vector<double> solid_volume;       // sum w (1 - n_p) V_p
  std::vector<double> mass;               // sum w m_p
  std::vector<double> momentum;           // sum w m_p v_p, Dim per cell
  std::vector<double> volume_momentum;    // sum w (1 - n_p) V_p v_p, Dim per cell
  std::vector<double> porous_mass;        // sum w m_p over porous points
  std::vector<double> permeability_mass;  // sum w m_p kappa_p over porous points
  std::vector<double> grain_size_mass;    // sum w m_p D50_p over porous points

  CellSolidSums(std::size_t cells, int dim);
  // Moves `fraction` of cell `from`'s sums to cell `to`.
  void move(std::size_t from, std::size_t to, double fraction);
  // Calls f(array) for each of the arrays above.
  template <class F>
  void for_each_array(F&& f) {
    for (auto* v : {&domain, &solid_volume, &mass, &momentum, &volume_momentum, &porous_mass,
                    &permeability_mass, &grain_size_mass})
      f(*v);
  }

 private:
  std::size_t dim_;
};

// Where a deformable body's points cluster (they drift into stacks in a
// shearing flow), their domains cover more than a cell's volume and the
// cell's solid fraction exceeds the points' own 1 - n_p, up to solid cells
// inside a porous soil; a cell beside it is left as short. The free solid's
// share beyond the cell's room (its volume less what all domains cover, with
// a tolerance of 0.1 %) is handed to its face neighbours, each taking at most
// its room times the fraction of it the body's points already fill (their
// particles take what the cell is given back; nothing jumps as a neighbour
// is first reached), over a few sweeps. Solid volume, mass and momentum are
// only moved, never changed. Returns the number of cells overfilled beyond
// the tolerance.
// On a rank of a decomposed MPM: every rank's sums in `free` and `held`, in
// one collective sum.
void sum_cells_over_ranks(CellSolidSums& free, CellSolidSums& held, const SumOverRanks& sum);

template <int Dim>
std::size_t spread_overfilled_cells(const ExchangeGrid<Dim>& grid, CellSolidSums& free,
                                    const CellSolidSums& held);

}  // namespace mpm::coupling
