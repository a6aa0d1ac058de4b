#pragma once

#include <cstring>
#include <ranges>

namespace cosim::testing {

// Whether two arrays hold the same values in every bit (NaNs and signed
// zeros included). Empty arrays compare equal without touching their data,
// which may be null.
// The values are compared as bytes: plain numbers or fixed-size Eigen
// vectors and matrices (no padding, no pointers).
template <std::ranges::contiguous_range Range>
bool same_bits(const Range& a, const Range& b) {
  const auto n = std::ranges::size(a);
  return n == std::ranges::size(b) &&
         (n == 0 || std::memcmp(std::ranges::data(a), std::ranges::data(b),
                                n * sizeof(std::ranges::range_value_t<Range>)) == 0);
}

}  // namespace cosim::testing
