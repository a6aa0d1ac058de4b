#include "block_weights.hpp"

#include <cmath>
#include <numeric>

namespace cosim::acceleration {

namespace {

double norm(std::span<const double> v) {
  return std::sqrt(std::inner_product(v.begin(), v.end(), v.begin(), 0.0));
}

}  // namespace

BlockWeights::BlockWeights(Preconditioner kind, std::vector<Block> blocks, std::size_t freeze_after)
    : kind_(kind),
      blocks_(std::move(blocks)),
      freeze_after_(freeze_after),
      weights_(blocks_.size(), 1.0),
      residual_sums_(blocks_.size(), 0.0) {
  std::size_t offset = 0;
  for (const Block& b : blocks_) {
    offsets_.push_back(offset);
    offset += b.size;
  }
}

std::span<const double> BlockWeights::slice(std::span<const double> v, std::size_t block) const {
  return v.subspan(offsets_[block], blocks_[block].size);
}

void BlockWeights::update(std::span<const double> x, std::span<const double> r,
                          bool first_of_window) {
  if (kind_ == Preconditioner::none || (freeze_after_ > 0 && windows_ >= freeze_after_)) return;
  if (kind_ == Preconditioner::value) {
    if (!first_of_window) return;
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
      const double n = norm(slice(x, b));
      weights_[b] = n > 0.0 ? 1.0 / n : 1.0;
    }
    return;
  }
  const double total = norm(r);
  if (!(total > 0.0)) return;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    residual_sums_[b] += norm(slice(r, b)) / total;
    weights_[b] = residual_sums_[b] > 0.0 ? 1.0 / residual_sums_[b] : 1.0;
  }
}

void BlockWeights::window_converged() {
  ++windows_;
  if (freeze_after_ > 0 && windows_ >= freeze_after_) return;
  std::fill(residual_sums_.begin(), residual_sums_.end(), 0.0);
}

double BlockWeights::dot(std::span<const double> a, std::span<const double> c) const {
  double sum = 0.0;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const auto ab = slice(a, b), cb = slice(c, b);
    sum += weights_[b] * weights_[b] * std::inner_product(ab.begin(), ab.end(), cb.begin(), 0.0);
  }
  return sum;
}

void BlockWeights::scale(std::span<double> v) const {
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    for (std::size_t i = 0; i < blocks_[b].size; ++i) v[offsets_[b] + i] *= weights_[b];
}

void BlockWeights::save(AcceleratorState& s) const {
  s.scalars.push_back(static_cast<double>(windows_));
  s.vectors.push_back(weights_);
  s.vectors.push_back(residual_sums_);
}

std::size_t BlockWeights::restore(const AcceleratorState& s, std::size_t first_vector) {
  windows_ = static_cast<std::size_t>(s.scalars.at(0));
  weights_ = s.vectors.at(first_vector);
  residual_sums_ = s.vectors.at(first_vector + 1);
  return first_vector + 2;
}

}  // namespace cosim::acceleration
