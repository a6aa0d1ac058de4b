#include "iqn_ils.hpp"

#include <Eigen/Dense>

#include "qr_filter.hpp"

namespace cosim::acceleration {

IqnIls::IqnIls(const AccelerationSpec& spec, BlockWeights weights)
    : spec_(spec), weights_(std::move(weights)) {}

void IqnIls::add_column(const std::vector<double>& r, std::span<const double> h) {
  std::vector<double> v(r.size()), w(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    v[i] = r[i] - previous_residual_[i];
    w[i] = h[i] - previous_answer_[i];
  }
  v_.push_front(std::move(v));
  w_.push_front(std::move(w));
  column_window_.push_front(window_);
  while (v_.size() > spec_.max_columns) {
    v_.pop_back();
    w_.pop_back();
    column_window_.pop_back();
  }
}

void IqnIls::accelerate(std::span<const double> x, std::span<const double> h,
                        std::span<double> next) {
  const std::size_t n = x.size();
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = h[i] - x[i];
  weights_.update(x, r, first_of_window_);
  if (!first_of_window_) add_column(r, h);
  previous_residual_ = r;
  previous_answer_.assign(h.begin(), h.end());
  first_of_window_ = false;

  if (v_.empty()) {
    for (std::size_t i = 0; i < n; ++i) next[i] = x[i] + spec_.relaxation * r[i];
    return;
  }
  // The least-squares system in the weighted norm: min ||P (V c + r)||.
  const auto rows = static_cast<Eigen::Index>(n);
  Eigen::MatrixXd v(rows, static_cast<Eigen::Index>(v_.size()));
  for (std::size_t j = 0; j < v_.size(); ++j) {
    std::vector<double> column = v_[j];
    weights_.scale(column);
    v.col(static_cast<Eigen::Index>(j)) = Eigen::Map<const Eigen::VectorXd>(column.data(), rows);
  }
  const FilteredQR qr = filtered_qr(v, spec_.filter, spec_.filter_limit);
  // A column the filter drops carries no information now and will not later.
  if (qr.kept.size() < v_.size()) {
    std::deque<std::vector<double>> kept_v, kept_w;
    std::deque<std::size_t> kept_window;
    for (std::size_t j : qr.kept) {
      kept_v.push_back(std::move(v_[j]));
      kept_w.push_back(std::move(w_[j]));
      kept_window.push_back(column_window_[j]);
    }
    v_ = std::move(kept_v);
    w_ = std::move(kept_w);
    column_window_ = std::move(kept_window);
  }
  std::vector<double> scaled_r = r;
  weights_.scale(scaled_r);
  const Eigen::VectorXd rhs =
      -qr.q.transpose() * Eigen::Map<const Eigen::VectorXd>(scaled_r.data(), rows);
  const Eigen::VectorXd c = qr.r.triangularView<Eigen::Upper>().solve(rhs);
  for (std::size_t i = 0; i < n; ++i) next[i] = h[i];
  for (std::size_t j = 0; j < w_.size(); ++j) {
    const double cj = c[static_cast<Eigen::Index>(j)];
    for (std::size_t i = 0; i < n; ++i) next[i] += cj * w_[j][i];
  }
}

void IqnIls::window_converged(std::span<const double> x, std::span<const double> h) {
  if (!first_of_window_) {
    std::vector<double> r(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) r[i] = h[i] - x[i];
    add_column(r, h);
  }
  ++window_;
  // Keep the columns of the last reuse_windows windows, this one included.
  while (!column_window_.empty() &&
         (spec_.reuse_windows == 0 || column_window_.back() + spec_.reuse_windows < window_)) {
    v_.pop_back();
    w_.pop_back();
    column_window_.pop_back();
  }
  first_of_window_ = true;
  previous_residual_.clear();
  previous_answer_.clear();
  weights_.window_converged();
}

AcceleratorState IqnIls::state() const {
  AcceleratorState s;
  weights_.save(s);
  s.scalars.push_back(static_cast<double>(window_));
  s.scalars.push_back(first_of_window_ ? 1.0 : 0.0);
  s.vectors.push_back(previous_residual_);
  s.vectors.push_back(previous_answer_);
  s.vectors.push_back(std::vector<double>(column_window_.begin(), column_window_.end()));
  for (std::size_t j = 0; j < v_.size(); ++j) {
    s.vectors.push_back(v_[j]);
    s.vectors.push_back(w_[j]);
  }
  return s;
}

void IqnIls::restore(const AcceleratorState& s) {
  std::size_t k = weights_.restore(s, 0);
  window_ = static_cast<std::size_t>(s.scalars.at(1));
  first_of_window_ = s.scalars.at(2) != 0.0;
  previous_residual_ = s.vectors.at(k++);
  previous_answer_ = s.vectors.at(k++);
  const std::vector<double>& windows = s.vectors.at(k++);
  v_.clear();
  w_.clear();
  column_window_.clear();
  for (double w : windows) {
    column_window_.push_back(static_cast<std::size_t>(w));
    v_.push_back(s.vectors.at(k++));
    w_.push_back(s.vectors.at(k++));
  }
}

}  // namespace cosim::acceleration
