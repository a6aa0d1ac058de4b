#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::detail {

// Particles binned into slabs of whole cell rows along the last direction,
// for a particle-to-grid scatter that is parallel and yet deterministic: a
// point touches grid values at most one cell row beyond its own cell on
// either side (support <= 3), so slabs at least three rows thick that share
// a colour (even / odd) never write the same grid value. Slabs of one
// colour run in parallel, the colours one after the other, and each slab
// visits its particles in index order, so every grid value receives its
// contributions in the same order whatever the thread count.
class ParticleBins {
 public:
  template <int Dim>
  void build(const Particles<Dim>& particles, const Grid<Dim>& grid, int threads) {
    parallel_ = particles.size() >= 8192;  // see parallel_threshold in solver.cpp
    const int rows = grid.cells[Dim - 1];
    const int wanted = std::max(1, 4 * threads);  // several slabs per thread and colour
    slab_rows_ = std::max(3, rows / (2 * wanted));
    const int slabs = (rows + slab_rows_ - 1) / slab_rows_;
    begin_.assign(static_cast<std::size_t>(slabs) + 1, 0);
    slab_of_.resize(particles.size());
    const double inv_h = 1.0 / grid.spacing[Dim - 1];
    const double origin = grid.origin[Dim - 1];
    for (std::size_t p = 0; p < particles.size(); ++p) {
      double row = std::floor((particles.position[p][Dim - 1] - origin) * inv_h);
      row = std::clamp(row, 0.0, static_cast<double>(rows - 1));
      const auto slab = static_cast<std::uint32_t>(static_cast<int>(row) / slab_rows_);
      slab_of_[p] = slab;
      ++begin_[slab + 1];
    }
    for (std::size_t s = 1; s < begin_.size(); ++s) begin_[s] += begin_[s - 1];
    order_.resize(particles.size());
    std::vector<std::size_t> next(begin_.begin(), begin_.end() - 1);
    for (std::size_t p = 0; p < particles.size(); ++p)
      order_[next[slab_of_[p]]++] = static_cast<std::uint32_t>(p);
  }

  int slabs() const { return static_cast<int>(begin_.size()) - 1; }

  // f(particle) for every particle, slab-coloured as described above.
  template <class F>
  void scatter(F&& f) const {
    const int n = slabs();
    for (int colour = 0; colour < 2; ++colour) {
#pragma omp parallel for schedule(dynamic, 1) if (parallel_)
      for (int s = colour; s < n; s += 2) {
        for (std::size_t k = begin_[s]; k < begin_[s + 1]; ++k)
          f(static_cast<std::size_t>(order_[k]));
      }
    }
  }

  // f(particle) for every particle of each slab, slabs in parallel: for
  // writes to the particle's own cell only (cells never span slabs).
  template <class F>
  void per_slab(F&& f) const {
    const int n = slabs();
#pragma omp parallel for schedule(dynamic, 1) if (parallel_)
    for (int s = 0; s < n; ++s) {
      for (std::size_t k = begin_[s]; k < begin_[s + 1]; ++k)
        f(static_cast<std::size_t>(order_[k]));
    }
  }

 private:
  int slab_rows_ = 3;
  bool parallel_ = true;
  std::vector<std::size_t> begin_;
  std::vector<std::uint32_t> order_;
  std::vector<std::uint32_t> slab_of_;
};

}  // namespace mpm::detail
