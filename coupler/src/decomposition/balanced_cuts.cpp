#include "cosim/decomposition/balanced_cuts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim::decomposition {

std::vector<std::int64_t> balanced_cuts(std::span<const double> weights, int parts,
                                        std::int64_t min_slabs) {
  const auto n = static_cast<std::int64_t>(weights.size());
  if (parts < 1 || min_slabs < 1 || n < parts * min_slabs)
    throw std::invalid_argument(fmt::format(
        "balanced_cuts: {} slabs cannot make {} parts of at least {} slabs", n, parts, min_slabs));
  std::vector<double> before(weights.size() + 1, 0.0);  // weight of slabs [0, i)
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (!(weights[i] >= 0.0) || !std::isfinite(weights[i]))
      throw std::invalid_argument(fmt::format("balanced_cuts: slab {} weighs {}", i, weights[i]));
    before[i + 1] = before[i] + weights[i];
  }
  const double total = before.back();
  std::vector<std::int64_t> cuts(static_cast<std::size_t>(parts) + 1, 0);
  cuts.back() = n;
  for (int p = 1; p < parts; ++p) {
    const std::int64_t lowest = cuts[static_cast<std::size_t>(p) - 1] + min_slabs;
    const std::int64_t highest = n - (parts - p) * min_slabs;
    std::int64_t cut;
    if (total > 0.0) {
      const double target = total * p / parts;
      // The first boundary with at least the target before it, or the one
      // before it, whichever is nearer.
      const auto first = std::lower_bound(before.begin(), before.end(), target);
      cut = static_cast<std::int64_t>(first - before.begin());
      if (cut > 0 && target - before[static_cast<std::size_t>(cut) - 1] <
                         before[static_cast<std::size_t>(cut)] - target)
        --cut;
    } else {
      cut = n * p / parts;
    }
    cuts[static_cast<std::size_t>(p)] = std::clamp(cut, lowest, highest);
  }
  return cuts;
}

double imbalance(std::span<const double> weights, std::span<const std::int64_t> cuts) {
  if (cuts.size() < 2) throw std::invalid_argument("imbalance: fewer than two cuts");
  double largest = 0.0, total = 0.0;
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
    double part = 0.0;
    for (auto i = cuts[p]; i < cuts[p + 1]; ++i) part += weights[static_cast<std::size_t>(i)];
    largest = std::max(largest, part);
    total += part;
  }
  const double mean = total / static_cast<double>(cuts.size() - 1);
  return mean > 0.0 ? largest / mean : 0.0;
}

}  // namespace cosim::decomposition
