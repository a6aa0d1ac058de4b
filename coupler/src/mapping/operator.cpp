#include "mapping/operator.hpp"

#include <Eigen/Core>
#include <string>
#include <utility>

#include "cosim/error.hpp"

namespace cosim::mapping {

Operator::Operator(Constraint constraint, Weights&& weights, std::string source_mesh,
                   std::string target_mesh, std::vector<std::size_t> empty_targets,
                   std::size_t fallback_sources)
    : constraint_(constraint),
      source_mesh_(std::move(source_mesh)),
      target_mesh_(std::move(target_mesh)),
      empty_targets_(std::move(empty_targets)),
      fallback_sources_(fallback_sources) {
  weights_.swap(weights);
  weights_.makeCompressed();
}

Operator::Operator(Operator&& other) noexcept
    : constraint_(other.constraint_),
      source_mesh_(std::move(other.source_mesh_)),
      target_mesh_(std::move(other.target_mesh_)),
      empty_targets_(std::move(other.empty_targets_)),
      fallback_sources_(other.fallback_sources_) {
  weights_.swap(other.weights_);
}

Operator& Operator::operator=(Operator&& other) noexcept {
  constraint_ = other.constraint_;
  weights_.swap(other.weights_);
  source_mesh_ = std::move(other.source_mesh_);
  target_mesh_ = std::move(other.target_mesh_);
  empty_targets_ = std::move(other.empty_targets_);
  fallback_sources_ = other.fallback_sources_;
  return *this;
}

void Operator::apply(std::span<const double> source, std::span<double> target,
                     int components) const {
  if (components < 1)
    throw InputError("mapping '" + source_mesh_ + "' -> '" + target_mesh_ + "': component count " +
                     std::to_string(components) + " is not positive");
  const auto c = static_cast<std::size_t>(components);
  if (source.size() != source_size() * c || target.size() != target_size() * c)
    throw InputError("mapping '" + source_mesh_ + "' -> '" + target_mesh_ + "' with " +
                     std::to_string(components) + " component(s) expects " +
                     std::to_string(source_size() * c) + " source and " +
                     std::to_string(target_size() * c) + " target values, got " +
                     std::to_string(source.size()) + " and " + std::to_string(target.size()));
  const auto rows = weights_.rows();
  const auto cols = weights_.cols();
  if (components == 1) {
    Eigen::Map<const Eigen::VectorXd> x(source.data(), cols);
    Eigen::Map<Eigen::VectorXd> y(target.data(), rows);
    y.noalias() = weights_ * x;
    return;
  }
  using ElementMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Eigen::Map<const ElementMajor> x(source.data(), cols, components);
  Eigen::Map<ElementMajor> y(target.data(), rows, components);
  y.noalias() = weights_ * x;
}

std::vector<double> Operator::apply(std::span<const double> source, int components) const {
  std::vector<double> target(target_size() *
                             static_cast<std::size_t>(components > 0 ? components : 0));
  apply(source, target, components);
  return target;
}

}  // namespace cosim::mapping
