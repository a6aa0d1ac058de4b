#include "multi_vector_jacobian.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace cosim::acceleration {

MultiVectorJacobian::MultiVectorJacobian(std::size_t windows, std::size_t size)
    : windows_(windows), size_(size) {}

Eigen::VectorXd MultiVectorJacobian::times(const Eigen::VectorXd& y) const {
  Eigen::VectorXd product = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size_));
  for (const Update& u : updates_) product.noalias() += u.a * (u.z_transposed.transpose() * y);
  return product;
}

void MultiVectorJacobian::update(const Eigen::MatrixXd& v, const Eigen::MatrixXd& w,
                                 Eigen::MatrixXd z_transposed) {
  if (windows_ == 0 || v.cols() == 0) return;
  Eigen::MatrixXd a = w;
  for (Eigen::Index c = 0; c < v.cols(); ++c) a.col(c) -= times(v.col(c));
  updates_.push_front({std::move(a), std::move(z_transposed)});
  if (updates_.size() > windows_) updates_.pop_back();
}

void MultiVectorJacobian::write(detail::StateWriter& writer) const {
  writer.count(updates_.size());
  for (const Update& u : updates_) {
    writer.count(static_cast<std::size_t>(u.a.cols()));
    for (Eigen::Index c = 0; c < u.a.cols(); ++c) {
      writer.vector(Eigen::VectorXd(u.a.col(c)));
      writer.vector(Eigen::VectorXd(u.z_transposed.col(c)));
    }
  }
}

void MultiVectorJacobian::read(detail::StateReader& reader) {
  const std::size_t count = reader.count("Jacobian update count");
  if (count > windows_)
    throw std::invalid_argument("acceleration: cannot restore the state: it has " +
                                std::to_string(count) + " Jacobian updates, more than " +
                                "reuse_windows " + std::to_string(windows_));
  std::deque<Update> updates;
  const auto rows = static_cast<Eigen::Index>(size_);
  for (std::size_t m = 0; m < count; ++m) {
    const auto columns = static_cast<Eigen::Index>(reader.count("Jacobian update's columns"));
    Update u{Eigen::MatrixXd(rows, columns), Eigen::MatrixXd(rows, columns)};
    for (Eigen::Index c = 0; c < columns; ++c) {
      u.a.col(c) = reader.vector("column of a Jacobian update", size_);
      u.z_transposed.col(c) = reader.vector("column of a Jacobian update's Z", size_);
    }
    updates.push_back(std::move(u));
  }
  updates_ = std::move(updates);
}

}  // namespace cosim::acceleration
