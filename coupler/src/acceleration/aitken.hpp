#pragma once

#include <vector>

#include "accelerator.hpp"
#include "block_weights.hpp"

namespace cosim::acceleration {

// Aitken's dynamic relaxation (Kuettler & Wall 2008), with r = H(x) - x
// and the preconditioner's weighted inner product:
//   omega_k = -omega_{k-1} r_{k-1} . (r_k - r_{k-1}) / ||r_k - r_{k-1}||^2,
//   x^{k+1} = x^k + omega_k r_k.
// A window's first iteration takes the initial factor, with the sign of the
// last window's final one and no larger in magnitude (as preCICE does).
class Aitken final : public Accelerator {
 public:
  Aitken(double initial, BlockWeights weights);
  void accelerate(std::span<const double> x, std::span<const double> h,
                  std::span<double> next) override;
  void window_converged(std::span<const double> x, std::span<const double> h) override;
  AcceleratorState state() const override;
  void restore(const AcceleratorState& s) override;

  double factor() const { return omega_; }

 private:
  double initial_;
  BlockWeights weights_;
  double omega_;
  bool first_of_window_ = true;
  std::vector<double> previous_residual_;
};

}  // namespace cosim::acceleration
