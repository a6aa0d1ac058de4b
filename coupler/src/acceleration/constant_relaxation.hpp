#pragma once

#include "accelerator.hpp"

namespace cosim::acceleration {

// x^{k+1} = x^k + omega (H(x^k) - x^k); omega = 1 takes H(x^k) as it is.
class ConstantRelaxation final : public Accelerator {
 public:
  explicit ConstantRelaxation(double omega) : omega_(omega) {}
  void accelerate(std::span<const double> x, std::span<const double> h,
                  std::span<double> next) override;
  void window_converged(std::span<const double>, std::span<const double>) override {}
  AcceleratorState state() const override { return {}; }
  void restore(const AcceleratorState&) override {}

 private:
  double omega_;
};

}  // namespace cosim::acceleration
