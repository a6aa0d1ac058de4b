#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::detail {

// Particles binned into slabs of `slab_rows` whole cell rows along the last
// direction, counted from the grid's first row: a particle-to-grid scatter
// that runs in parallel and gives every grid value the same bits whatever
// the thread count or the ranks the grid is split over.
//
// A point touches grid values at most one cell row below and two above its
// own cell, so a grid value receives from at most two slabs, one even and
// one odd, and two slabs of one parity never write the same value. The even
// slabs add into the grid's arrays, the odd slabs into a second set
// (scatter() tells f the parity), all slabs at once; then each value is
// even + odd (add_odd_partials). Each slab visits its particles in index
// order. The slabs depend on the grid alone, so a decomposed grid cut at
// slab boundaries gives its values the same partial sums as one process.
class ParticleBins {
 public:
  static constexpr int slab_rows = 4;

  static int slab_of_row(int row) { return row / slab_rows; }

  template <int Dim>
  void build(const Particles<Dim>& particles, const Grid<Dim>& grid) {
    parallel_ = particles.size() >= 8192;  // see parallel_threshold in solver.cpp
    const int rows = grid.cells[Dim - 1];
    const int slabs = (rows + slab_rows - 1) / slab_rows;
    begin_.assign(static_cast<std::size_t>(slabs) + 1, 0);
    slab_of_.resize(particles.size());
    const double inv_h = 1.0 / grid.spacing[Dim - 1];
    const double origin = grid.origin[Dim - 1];
    for (std::size_t p = 0; p < particles.size(); ++p) {
      double row = std::floor((particles.position[p][Dim - 1] - origin) * inv_h);
      row = std::clamp(row, 0.0, static_cast<double>(rows - 1));
      const auto slab = static_cast<std::uint32_t>(slab_of_row(static_cast<int>(row)));
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

  // f(particle, parity) for every particle; f adds into the partial sums of
  // the slab's parity (0 even, 1 odd), as described above.
  template <class F>
  void scatter(F&& f) const {
    const int n = slabs();
#pragma omp parallel for schedule(dynamic, 1) if (parallel_)
    for (int s = 0; s < n; ++s) {
      for (std::size_t k = begin_[s]; k < begin_[s + 1]; ++k)
        f(static_cast<std::size_t>(order_[k]), s % 2);
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
  bool parallel_ = true;
  std::vector<std::size_t> begin_;
  std::vector<std::uint32_t> order_;
  std::vector<std::uint32_t> slab_of_;
};

inline void set_zero(double& x) {
  x = 0.0;
}
template <class Derived>
void set_zero(Eigen::MatrixBase<Derived>& x) {
  x.setZero();
}

// A scattered array's value: the even slabs' partial sum (in `even`) plus
// the odd slabs' (`odd`, zero between scatters and zeroed again here), in
// that order.
template <class T>
void add_odd_partials(std::vector<T>& even, std::vector<T>& odd, bool parallel) {
  const auto n = static_cast<std::ptrdiff_t>(even.size());
#pragma omp parallel for schedule(static) if (parallel)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    even[k] = even[k] + odd[k];
    set_zero(odd[k]);
  }
}

}  // namespace mpm::detail
