#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "accelerator.hpp"

namespace cosim::acceleration {

// Per-field scaling of the residuals in the accelerators' inner products
// (preCICE's preconditioners), so that fields of different units and sizes
// weigh alike:
//   none          w_b = 1
//   value         w_b = 1 / ||x_b|| of the window's first iterate
//   residual_sum  w_b = 1 / sum_k ||r_b^k|| / ||r^k|| over the window's
//                 iterations so far
// The weights stop changing after `freeze_after` windows (0: never).
class BlockWeights {
 public:
  BlockWeights(Preconditioner kind, std::vector<Block> blocks, std::size_t freeze_after);

  // Called at every iteration with the iterate and its residual.
  void update(std::span<const double> x, std::span<const double> r, bool first_of_window);
  void window_converged();

  double weight(std::size_t block) const { return weights_[block]; }
  // sum_b w_b^2 a_b . c_b
  double dot(std::span<const double> a, std::span<const double> c) const;
  // v scaled in place by its block's weight.
  void scale(std::span<double> v) const;

  void save(AcceleratorState& s) const;
  std::size_t restore(const AcceleratorState& s, std::size_t first_vector);

 private:
  std::span<const double> slice(std::span<const double> v, std::size_t block) const;

  Preconditioner kind_;
  std::vector<Block> blocks_;
  std::vector<std::size_t> offsets_;
  std::size_t freeze_after_;
  std::size_t windows_ = 0;
  std::vector<double> weights_;
  std::vector<double> residual_sums_;
};

}  // namespace cosim::acceleration
