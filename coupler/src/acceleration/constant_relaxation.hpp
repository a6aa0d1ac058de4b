#pragma once

#include <cstddef>

#include "acceleration/accelerator.hpp"

namespace cosim::acceleration {

// x^{k+1} = x^k + omega (H(x^k) - x^k).
class ConstantRelaxation final : public Accelerator {
 public:
  ConstantRelaxation(double omega, std::size_t size) : omega_(omega), size_(size) {}

  void accelerate(std::span<const double> x, std::span<const double> h,
                  std::span<double> next) override;
  void window_converged(std::span<const double> x, std::span<const double> h) override;
  AcceleratorState state() const override;
  void restore(const AcceleratorState& s) override;

 private:
  double omega_;
  std::size_t size_;
};

}  // namespace cosim::acceleration
