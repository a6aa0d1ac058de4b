#include "preconditioner.hpp"

#include <algorithm>
#include <utility>

namespace cosim::acceleration {

namespace {

// The norm of each block's slice of v.
std::vector<double> block_norms(const std::vector<Block>& blocks,
                                const Eigen::Ref<const Eigen::VectorXd>& v) {
  std::vector<double> norms;
  norms.reserve(blocks.size());
  Eigen::Index offset = 0;
  for (const Block& block : blocks) {
    const auto size = static_cast<Eigen::Index>(block.size);
    norms.push_back(v.segment(offset, size).norm());
    offset += size;
  }
  return norms;
}

}  // namespace

PreconditionerWeights::PreconditionerWeights(Preconditioner kind, std::vector<Block> blocks,
                                             std::size_t freeze_after)
    : kind_(kind),
      blocks_(std::move(blocks)),
      freeze_after_(freeze_after),
      weights_(blocks_.size(), 1.0),
      residual_sums_(blocks_.size(), 0.0) {}

void PreconditionerWeights::update(const Eigen::Ref<const Eigen::VectorXd>& x,
                                   const Eigen::Ref<const Eigen::VectorXd>& r) {
  const bool first_iteration = iterations_in_window_ == 0;
  ++iterations_in_window_;
  if (frozen()) return;
  switch (kind_) {
    case Preconditioner::none:
      break;
    case Preconditioner::value:
      if (first_iteration) {
        const std::vector<double> norms = block_norms(blocks_, x);
        for (std::size_t b = 0; b < blocks_.size(); ++b)
          weights_[b] = norms[b] > 0.0 ? 1.0 / norms[b] : 1.0;
      }
      break;
    case Preconditioner::residual_sum: {
      const double residual_norm = r.norm();
      if (residual_norm == 0.0) break;
      const std::vector<double> norms = block_norms(blocks_, r);
      for (std::size_t b = 0; b < blocks_.size(); ++b) {
        residual_sums_[b] += norms[b] / residual_norm;
        if (residual_sums_[b] > 0.0) weights_[b] = 1.0 / residual_sums_[b];
      }
      break;
    }
    case Preconditioner::convergence: {
      const std::vector<double> residual_norms = block_norms(blocks_, r);
      const std::vector<double> answer_norms = block_norms(blocks_, x + r);
      if (first_iteration) first_residual_norms_ = residual_norms;
      for (std::size_t b = 0; b < blocks_.size(); ++b) {
        const Block& block = blocks_[b];
        const double tolerance = std::max({block.relative * answer_norms[b], block.absolute,
                                           block.residual_relative * first_residual_norms_[b]});
        if (tolerance > 0.0)
          weights_[b] = 1.0 / tolerance;
        else if (answer_norms[b] > 0.0)
          weights_[b] = 1.0 / answer_norms[b];
      }
      break;
    }
  }
}

void PreconditionerWeights::window_converged() {
  ++converged_windows_;
  iterations_in_window_ = 0;
  residual_sums_.assign(blocks_.size(), 0.0);
}

void PreconditionerWeights::apply(Eigen::Ref<Eigen::MatrixXd> rows) const {
  Eigen::Index offset = 0;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const auto size = static_cast<Eigen::Index>(blocks_[b].size);
    rows.middleRows(offset, size) *= weights_[b];
    offset += size;
  }
}

void PreconditionerWeights::write(detail::StateWriter& writer) const {
  writer.count(iterations_in_window_);
  writer.count(converged_windows_);
  writer.vector(weights_);
  writer.vector(residual_sums_);
}

void PreconditionerWeights::read(detail::StateReader& reader) {
  iterations_in_window_ = reader.count("preconditioner's iterations in the window");
  converged_windows_ = reader.count("preconditioner's converged windows");
  weights_ = reader.values("preconditioner weights", blocks_.size());
  residual_sums_ = reader.values("preconditioner residual sums", blocks_.size());
}

}  // namespace cosim::acceleration
