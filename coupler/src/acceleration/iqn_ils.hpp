#pragma once

#include <deque>
#include <vector>

#include "accelerator.hpp"
#include "block_weights.hpp"

namespace cosim::acceleration {

// Interface quasi-Newton with an inverse Jacobian from a least-squares model
// (IQN-ILS; Degroote et al. 2009). With r^k = H(x^k) - x^k, the columns
//   V = [r^k - r^{k-1}, ...],  W = [H(x^k) - H(x^{k-1}), ...]  (newest first)
// give c = argmin ||V c + r^k|| (weighted by the block weights, V filtered
// and decomposed by filtered_qr), and
//   x^{k+1} = H(x^k) + W c.
// Columns of the last `reuse_windows` converged windows stay (Haelterman et
// al. 2016), at most `max_columns` in all, the oldest dropped first; with no
// column the step is constant relaxation.
class IqnIls final : public Accelerator {
 public:
  IqnIls(const AccelerationSpec& spec, BlockWeights weights);
  void accelerate(std::span<const double> x, std::span<const double> h,
                  std::span<double> next) override;
  void window_converged(std::span<const double> x, std::span<const double> h) override;
  AcceleratorState state() const override;
  void restore(const AcceleratorState& s) override;
  std::size_t columns() const override { return v_.size(); }

 private:
  struct Column {
    std::vector<double> v, w;
    std::size_t window;  // the window it was made in
  };
  void add_column(const std::vector<double>& r, std::span<const double> h);

  AccelerationSpec spec_;
  BlockWeights weights_;
  std::deque<std::vector<double>> v_, w_;  // newest first
  std::deque<std::size_t> column_window_;
  std::size_t window_ = 0;  // converged windows so far
  bool first_of_window_ = true;
  std::vector<double> previous_residual_, previous_answer_;
};

}  // namespace cosim::acceleration
