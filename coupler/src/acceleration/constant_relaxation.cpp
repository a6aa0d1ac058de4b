#include "constant_relaxation.hpp"

namespace cosim::acceleration {

void ConstantRelaxation::accelerate(std::span<const double> x, std::span<const double> h,
                                    std::span<double> next) {
  for (std::size_t i = 0; i < x.size(); ++i) next[i] = x[i] + omega_ * (h[i] - x[i]);
}

}  // namespace cosim::acceleration
