#pragma once

#include <Eigen/Core>
#include <cassert>
#include <span>
#include <vector>

#include "mpm/coupling/exchange_grid.hpp"
#include "mpm/coupling/over_ranks.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::coupling {

// Totals of one share-out, per component (per unit depth in 2D).
template <int N>
struct ShareTotals {
  using Amount = Eigen::Matrix<double, N, 1>;
  Amount received = Amount::Zero();  // sum over the cells
  Amount applied = Amount::Zero();   // sum over the particles
  Amount absorbed = Amount::Zero();  // kept by cells no particle shares in
};

// An extensive amount given per exchange cell (N components, cell-major),
// shared out over the particles by their weight W_p in each cell with the
// conservative weights w_pc of ExchangeGrid:
//   A_p = sum_c A_c W_p w_pc / sum_q W_q w_qc,
// so sum_p A_p = sum_c A_c to round-off over the cells some particle shares
// in. A cell nobody shares in passes its amount on to the cells of the 3^Dim
// block around it by their share weight (the coupler's mappings smear
// amounts a little past the solid's edge) unless it holds solid that keeps
// it (`holding_weight`, e.g. rigid bodies for an impulse); what no particle
// can take is absorbed. With `holders_share` the holding weight also counts
// in each cell's total, W_q -> W_q + H_q in the sum, and the holders' share
// is absorbed (a force per cell shared by solid volume, a rigid bed's part
// kept by the bed). On a rank of a decomposed MPM `sum_over_ranks` makes the
// weights every rank's, so each rank gives its own points their shares of
// the whole amount (`applied` is then this rank's part).
template <int Dim, int N>
ShareTotals<N> share_over_particles(const ExchangeGrid<Dim>& grid,
                                    std::span<const double> cell_amount,
                                    const Particles<Dim>& particles,
                                    std::span<const double> share_weight,
                                    std::span<const double> holding_weight,
                                    std::vector<Eigen::Matrix<double, N, 1>>& particle_amount,
                                    bool holders_share = false,
                                    const SumOverRanks& sum_over_ranks = {}) {
  using Amount = Eigen::Matrix<double, N, 1>;
  const std::size_t n = grid.size();
  assert(cell_amount.size() == n * N);
  // The share and holding weights per cell, one after the other: one sum
  // over the ranks.
  std::vector<double> weights(2 * n, 0.0);
  double* const weight = weights.data();
  double* const holding = weights.data() + n;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double W = share_weight[p], H = holding_weight.empty() ? 0.0 : holding_weight[p];
    if (W <= 0.0 && H <= 0.0) continue;
    grid.for_each_conservative(particles.position[p], particles.half_length[p],
                               [&](std::size_t c, double w) {
                                 weight[c] += w * W;
                                 holding[c] += w * H;
                               });
  }
  if (sum_over_ranks) sum_over_ranks(weights);
  std::vector<Amount> amount(n);
  ShareTotals<N> totals;
  for (std::size_t c = 0; c < n; ++c) {
    amount[c] = Eigen::Map<const Amount>(cell_amount.data() + c * N);
    totals.received += amount[c];
  }
  for (std::size_t c = 0; c < n; ++c) {
    if (weight[c] > 0.0 || holding[c] > 0.0 || amount[c].isZero(0.0)) continue;
    double around = 0.0;
    grid.for_each_neighbour(c, [&](std::size_t f) { around += weight[f]; });
    if (!(around > 0.0)) continue;
    const Amount moved = amount[c];
    grid.for_each_neighbour(c, [&](std::size_t f) {
      if (weight[f] > 0.0) amount[f] += moved * (weight[f] / around);
    });
    amount[c].setZero();
  }
  // Amount per unit of share weight in each cell.
  std::vector<Amount> per_weight(n, Amount::Zero());
  for (std::size_t c = 0; c < n; ++c) {
    if (weight[c] > 0.0) {
      const double total = holders_share ? weight[c] + holding[c] : weight[c];
      per_weight[c] = amount[c] / total;
      if (holders_share) totals.absorbed += amount[c] * (holding[c] / total);
    } else {
      totals.absorbed += amount[c];
    }
  }
  particle_amount.assign(particles.size(), Amount::Zero());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double W = share_weight[p];
    if (W <= 0.0) continue;
    Amount& a = particle_amount[p];
    grid.for_each_conservative(particles.position[p], particles.half_length[p],
                               [&](std::size_t c, double w) { a += (w * W) * per_weight[c]; });
    totals.applied += a;
  }
  return totals;
}

}  // namespace mpm::coupling
