#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "hdf5_reader.hpp"

namespace cosim::testing {

// The largest difference of two runs' values of a dataset, relative to the
// largest magnitude of the first's (infinite when their sizes differ).
inline double relative_difference(const Hdf5Reader& a, const Hdf5Reader& b,
                                  const std::string& path) {
  const auto x = a.doubles(path).values;
  const auto y = b.doubles(path).values;
  if (x.size() != y.size()) return std::numeric_limits<double>::infinity();
  double scale = 0.0, difference = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    scale = std::max(scale, std::abs(x[i]));
    difference = std::max(difference, std::abs(x[i] - y[i]));
  }
  return scale > 0.0 ? difference / scale : difference;
}

}  // namespace cosim::testing
