#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "acceleration/accelerator.hpp"

namespace cosim::acceleration {

// Dynamic relaxation by Aitken's Delta^2 method (Küttler & Wall 2008):
// x^{k+1} = x^k + omega_k r^k, r^k = H(x^k) - x^k, with
//   omega_k = -omega_{k-1} (r^{k-1} . (r^k - r^{k-1})) / ||r^k - r^{k-1}||^2.
// The first iteration of a window has no r^{k-1}; it takes the last factor of
// the previous window with its sign, its magnitude clamped to the initial
// relaxation: omega_0 = sign(omega_prev) min(omega_init, |omega_prev|), as
// preCICE does (the first window starts from omega_prev = omega_init). A
// problem that needed negative factors keeps relaxing in the right direction.
// When the factor is undefined (r^k = r^{k-1}) or came out zero, the next
// iteration uses the initial relaxation, so that the iteration cannot stall.
class Aitken final : public Accelerator {
 public:
  Aitken(double initial_relaxation, std::size_t size);

  void accelerate(std::span<const double> x, std::span<const double> h,
                  std::span<double> next) override;
  void window_converged(std::span<const double> x, std::span<const double> h) override;
  AcceleratorState state() const override;
  void restore(const AcceleratorState& s) override;

  // The factor of the last iteration.
  double omega() const { return omega_; }

 private:
  double initial_relaxation_;
  std::size_t size_;
  double omega_;
  bool window_has_residual_ = false;
  Eigen::VectorXd previous_residual_;
};

}  // namespace cosim::acceleration
