#include "sparse_weights.hpp"

#include <limits>
#include <string>

#include "cosim/error.hpp"

namespace cosim::mapping::detail {

Weights allocate_weights(std::size_t rows, std::size_t cols, std::size_t nonzeros) {
  constexpr auto index_limit =
      static_cast<std::size_t>(std::numeric_limits<Weights::StorageIndex>::max());
  if (rows > index_limit || cols > index_limit || nonzeros > index_limit)
    throw InputError("mapping operator of " + std::to_string(rows) + " x " + std::to_string(cols) +
                     " with " + std::to_string(nonzeros) +
                     " weights exceeds the 32-bit index range");
  Weights w(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
  w.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
  return w;
}

std::vector<std::size_t> normalise_rows(Weights& weights) {
  std::vector<std::size_t> empty_rows;
  const auto* outer = weights.outerIndexPtr();
  double* value = weights.valuePtr();
  for (Eigen::Index r = 0; r < weights.rows(); ++r) {
    double sum = 0.0;
    for (auto e = outer[r]; e < outer[r + 1]; ++e) sum += value[e];
    if (sum > 0.0) {
      for (auto e = outer[r]; e < outer[r + 1]; ++e) value[e] /= sum;
    } else {
      empty_rows.push_back(static_cast<std::size_t>(r));
    }
  }
  return empty_rows;
}

void scale_columns(Weights& weights, const std::vector<double>& scale) {
  const auto nonzeros = weights.nonZeros();
  const auto* column = weights.innerIndexPtr();
  double* value = weights.valuePtr();
  for (Eigen::Index e = 0; e < nonzeros; ++e)
    value[e] *= scale[static_cast<std::size_t>(column[e])];
}

Weights transposed(const Weights& weights) {
  Weights t = weights.transpose();
  t.makeCompressed();
  return t;
}

}  // namespace cosim::mapping::detail
