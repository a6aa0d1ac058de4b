#include "iqn_ils.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

#include "qr_filter.hpp"
#include "state_io.hpp"
#include "vector_view.hpp"

namespace cosim::acceleration {

IqnIls::IqnIls(const AccelerationSpec& spec, std::vector<Block> blocks)
    : method_(spec.method),
      relaxation_(spec.relaxation),
      max_columns_(spec.max_columns),
      reuse_windows_(spec.reuse_windows),
      filter_(spec.filter),
      filter_limit_(spec.filter_limit),
      size_(total_size(blocks)),
      weights_(spec.preconditioner, std::move(blocks), spec.freeze_preconditioner_after),
      previous_residual_(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size_))),
      previous_output_(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size_))),
      jacobian_(spec.method == Method::iqn_imvj ? spec.reuse_windows : 0, size_) {}

void IqnIls::add_pair(const Eigen::VectorXd& r, const Eigen::VectorXd& h) {
  if (window_has_pair_) {
    columns_.push_front({r - previous_residual_, h - previous_output_, window_});
    if (columns_.size() > max_columns_) columns_.pop_back();
  }
  previous_residual_ = r;
  previous_output_ = h;
  window_has_pair_ = true;
}

Eigen::VectorXd IqnIls::least_squares_coefficients(const Eigen::VectorXd& r) {
  Eigen::MatrixXd weighted_v(static_cast<Eigen::Index>(size_),
                             static_cast<Eigen::Index>(columns_.size()));
  for (std::size_t c = 0; c < columns_.size(); ++c)
    weighted_v.col(static_cast<Eigen::Index>(c)) = columns_[c].residual_difference;
  weights_.apply(weighted_v);
  Eigen::VectorXd weighted_r = r;
  weights_.apply(weighted_r);

  const FilteredQr qr = filtered_qr(weighted_v, filter_, filter_limit_);
  for (auto c = qr.dropped.rbegin(); c != qr.dropped.rend(); ++c)
    columns_.erase(columns_.begin() + static_cast<std::ptrdiff_t>(*c));

  const Eigen::VectorXd rhs = -(qr.q.transpose() * weighted_r);
  return qr.r.triangularView<Eigen::Upper>().solve(rhs);
}

void IqnIls::accelerate(std::span<const double> x, std::span<const double> h,
                        std::span<double> next) {
  detail::require_size(x, size_, "x");
  detail::require_size(h, size_, "H(x)");
  detail::require_size(next, size_, "the next iterate");
  const Eigen::VectorXd output = detail::as_eigen(h);
  const Eigen::VectorXd residual = output - detail::as_eigen(x);
  weights_.update(detail::as_eigen(x), residual);
  add_pair(residual, output);

  Eigen::VectorXd coefficients;
  if (!columns_.empty()) coefficients = least_squares_coefficients(residual);
  Eigen::VectorXd next_iterate;
  if (columns_.empty()) {
    next_iterate = jacobian_.empty() ? Eigen::VectorXd(detail::as_eigen(x) + relaxation_ * residual)
                                     : Eigen::VectorXd(output - jacobian_.times(residual));
  } else {
    next_iterate = output;
    Eigen::VectorXd unexplained_residual = residual;
    for (std::size_t j = 0; j < columns_.size(); ++j) {
      const double c = coefficients(static_cast<Eigen::Index>(j));
      next_iterate += c * columns_[j].output_difference;
      unexplained_residual += c * columns_[j].residual_difference;
    }
    if (!jacobian_.empty()) next_iterate -= jacobian_.times(unexplained_residual);
  }
  detail::as_eigen(next) = next_iterate;
}

void IqnIls::window_converged(std::span<const double> x, std::span<const double> h) {
  detail::require_size(x, size_, "x");
  detail::require_size(h, size_, "H(x)");
  const Eigen::VectorXd output = detail::as_eigen(h);
  add_pair(output - detail::as_eigen(x), output);
  if (method_ == Method::iqn_imvj) move_columns_into_jacobian();
  weights_.window_converged();
  window_has_pair_ = false;
  ++window_;
  while (!columns_.empty() && columns_.back().window + reuse_windows_ < window_)
    columns_.pop_back();
}

void IqnIls::move_columns_into_jacobian() {
  const auto rows = static_cast<Eigen::Index>(size_);
  Eigen::MatrixXd weighted_v(rows, static_cast<Eigen::Index>(columns_.size()));
  for (std::size_t c = 0; c < columns_.size(); ++c)
    weighted_v.col(static_cast<Eigen::Index>(c)) = columns_[c].residual_difference;
  weights_.apply(weighted_v);
  const FilteredQr qr = filtered_qr(weighted_v, filter_, filter_limit_);
  const auto kept = static_cast<Eigen::Index>(qr.kept.size());
  Eigen::MatrixXd v(rows, kept);
  Eigen::MatrixXd w(rows, kept);
  for (Eigen::Index c = 0; c < kept; ++c) {
    const Column& column = columns_[qr.kept[static_cast<std::size_t>(c)]];
    v.col(c) = column.residual_difference;
    w.col(c) = column.output_difference;
  }
  // Z^T = P Q R^-T, so that Z y = R^-1 Q^T P y = argmin_c ||P (V c - y)||.
  Eigen::MatrixXd z_transposed =
      qr.r.triangularView<Eigen::Upper>().solve(qr.q.transpose()).transpose();
  weights_.apply(z_transposed);
  jacobian_.update(v, w, std::move(z_transposed));
  columns_.clear();
}

AcceleratorState IqnIls::state() const {
  detail::StateWriter writer(method_, size_);
  writer.count(window_);
  writer.flag(window_has_pair_);
  writer.vector(previous_residual_);
  writer.vector(previous_output_);
  writer.count(columns_.size());
  for (const Column& column : columns_) {
    writer.count(column.window);
    writer.vector(column.residual_difference);
    writer.vector(column.output_difference);
  }
  weights_.write(writer);
  if (method_ == Method::iqn_imvj) jacobian_.write(writer);
  return writer.take();
}

void IqnIls::restore(const AcceleratorState& s) {
  detail::StateReader reader(s, method_, size_);
  const std::size_t window = reader.count("window count");
  const bool window_has_pair = reader.flag("window-has-pair flag");
  Eigen::VectorXd previous_residual = reader.vector("previous residual", size_);
  Eigen::VectorXd previous_output = reader.vector("previous output", size_);
  const std::size_t column_count = reader.count("column count");
  if (column_count > max_columns_)
    throw std::invalid_argument("acceleration: cannot restore the state: it has " +
                                std::to_string(column_count) + " columns, more than max_columns " +
                                std::to_string(max_columns_));
  std::deque<Column> columns;
  for (std::size_t c = 0; c < column_count; ++c) {
    const std::size_t column_window = reader.count("column's window");
    Eigen::VectorXd residual_difference = reader.vector("column of V", size_);
    Eigen::VectorXd output_difference = reader.vector("column of W", size_);
    columns.push_back(
        {std::move(residual_difference), std::move(output_difference), column_window});
  }
  PreconditionerWeights weights = weights_;
  weights.read(reader);
  MultiVectorJacobian jacobian = jacobian_;
  if (method_ == Method::iqn_imvj) jacobian.read(reader);
  reader.finish();

  window_ = window;
  window_has_pair_ = window_has_pair;
  previous_residual_ = std::move(previous_residual);
  previous_output_ = std::move(previous_output);
  columns_ = std::move(columns);
  weights_ = std::move(weights);
  jacobian_ = std::move(jacobian);
}

}  // namespace cosim::acceleration
