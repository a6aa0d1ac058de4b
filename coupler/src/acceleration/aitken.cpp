#include "aitken.hpp"

#include <algorithm>
#include <cmath>

namespace cosim::acceleration {

Aitken::Aitken(double initial, BlockWeights weights)
    : initial_(initial), weights_(std::move(weights)), omega_(initial) {}

void Aitken::accelerate(std::span<const double> x, std::span<const double> h,
                        std::span<double> next) {
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) r[i] = h[i] - x[i];
  weights_.update(x, r, first_of_window_);
  if (first_of_window_) {
    omega_ = std::copysign(std::min(initial_, std::abs(omega_)), omega_);
  } else {
    std::vector<double> dr(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) dr[i] = r[i] - previous_residual_[i];
    const double denominator = weights_.dot(dr, dr);
    if (denominator > 0.0) omega_ = -omega_ * weights_.dot(previous_residual_, dr) / denominator;
  }
  for (std::size_t i = 0; i < x.size(); ++i) next[i] = x[i] + omega_ * r[i];
  previous_residual_ = std::move(r);
  first_of_window_ = false;
}

void Aitken::window_converged(std::span<const double>, std::span<const double>) {
  first_of_window_ = true;
  weights_.window_converged();
}

AcceleratorState Aitken::state() const {
  AcceleratorState s;
  weights_.save(s);
  s.scalars.push_back(omega_);
  s.scalars.push_back(first_of_window_ ? 1.0 : 0.0);
  s.vectors.push_back(previous_residual_);
  return s;
}

void Aitken::restore(const AcceleratorState& s) {
  const std::size_t v = weights_.restore(s, 0);
  omega_ = s.scalars.at(1);
  first_of_window_ = s.scalars.at(2) != 0.0;
  previous_residual_ = s.vectors.at(v);
}

}  // namespace cosim::acceleration
