#include "constant_relaxation.hpp"

#include "state_io.hpp"
#include "vector_view.hpp"

namespace cosim::acceleration {

void ConstantRelaxation::accelerate(std::span<const double> x, std::span<const double> h,
                                    std::span<double> next) {
  detail::require_size(x, size_, "x");
  detail::require_size(h, size_, "H(x)");
  detail::require_size(next, size_, "the next iterate");
  for (std::size_t i = 0; i < size_; ++i) next[i] = x[i] + omega_ * (h[i] - x[i]);
}

void ConstantRelaxation::window_converged(std::span<const double> x, std::span<const double> h) {
  detail::require_size(x, size_, "x");
  detail::require_size(h, size_, "H(x)");
}

AcceleratorState ConstantRelaxation::state() const {
  return detail::StateWriter(Method::constant, size_).take();
}

void ConstantRelaxation::restore(const AcceleratorState& s) {
  detail::StateReader(s, Method::constant, size_).finish();
}

}  // namespace cosim::acceleration
