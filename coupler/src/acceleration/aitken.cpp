#include "aitken.hpp"

#include <algorithm>
#include <cmath>

#include "state_io.hpp"
#include "vector_view.hpp"

namespace cosim::acceleration {

Aitken::Aitken(double initial_relaxation, std::size_t size)
    : initial_relaxation_(initial_relaxation),
      size_(size),
      omega_(initial_relaxation),
      previous_residual_(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size))) {}

void Aitken::accelerate(std::span<const double> x, std::span<const double> h,
                        std::span<double> next) {
  detail::require_size(x, size_, "x");
  detail::require_size(h, size_, "H(x)");
  detail::require_size(next, size_, "the next iterate");
  const Eigen::VectorXd residual = detail::as_eigen(h) - detail::as_eigen(x);

  if (!window_has_residual_) {
    omega_ = std::copysign(std::min(initial_relaxation_, std::abs(omega_)), omega_);
  } else {
    const Eigen::VectorXd residual_change = residual - previous_residual_;
    const double change_squared = residual_change.squaredNorm();
    if (change_squared > 0.0)
      omega_ = -omega_ * previous_residual_.dot(residual_change) / change_squared;
    else
      omega_ = initial_relaxation_;
  }
  if (omega_ == 0.0 || !std::isfinite(omega_)) omega_ = initial_relaxation_;

  previous_residual_ = residual;
  window_has_residual_ = true;
  detail::as_eigen(next) = detail::as_eigen(x) + omega_ * residual;
}

void Aitken::window_converged(std::span<const double> x, std::span<const double> h) {
  detail::require_size(x, size_, "x");
  detail::require_size(h, size_, "H(x)");
  window_has_residual_ = false;
}

AcceleratorState Aitken::state() const {
  detail::StateWriter writer(Method::aitken, size_);
  writer.scalar(omega_);
  writer.flag(window_has_residual_);
  writer.vector(previous_residual_);
  return writer.take();
}

void Aitken::restore(const AcceleratorState& s) {
  detail::StateReader reader(s, Method::aitken, size_);
  const double omega = reader.scalar("relaxation factor");
  const bool window_has_residual = reader.flag("window-has-residual flag");
  Eigen::VectorXd previous_residual = reader.vector("previous residual", size_);
  reader.finish();
  omega_ = omega;
  window_has_residual_ = window_has_residual;
  previous_residual_ = std::move(previous_residual);
}

}  // namespace cosim::acceleration
