#pragma once

#include <Eigen/SparseCore>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "mapping/constraint.hpp"

namespace cosim::mapping {

// target × source sparse weights: target = W · source. Built once per mesh
// pair by build_operator() and rebuilt only when a mesh changes.
using Weights = Eigen::SparseMatrix<double, Eigen::RowMajor>;

class Operator {
 public:
  Operator() = default;
  // `empty_targets`: consistent maps, target elements whose row is empty.
  // `fallback_sources`: conservative maps, source elements that overlapped no
  // target element and were given whole to the nearest one.
  // Takes over `weights` (left empty).
  Operator(Constraint constraint, Weights&& weights, std::string source_mesh,
           std::string target_mesh, std::vector<std::size_t> empty_targets = {},
           std::size_t fallback_sources = 0);
  // Eigen 3.4 sparse matrices have no move constructor: these swap instead of copying.
  Operator(Operator&& other) noexcept;
  Operator& operator=(Operator&& other) noexcept;
  Operator(const Operator&) = default;
  Operator& operator=(const Operator&) = default;
  ~Operator() = default;

  Constraint constraint() const { return constraint_; }
  std::size_t source_size() const { return static_cast<std::size_t>(weights_.cols()); }
  std::size_t target_size() const { return static_cast<std::size_t>(weights_.rows()); }
  const std::string& source_mesh() const { return source_mesh_; }
  const std::string& target_mesh() const { return target_mesh_; }
  const Weights& weights() const { return weights_; }

  // Values are element-major: `components` consecutive values per element.
  // Targets with an empty row receive 0 (see empty_target_indices()).
  // `source` and `target` must not overlap. Throws InputError on a size mismatch.
  void apply(std::span<const double> source, std::span<double> target, int components = 1) const;
  std::vector<double> apply(std::span<const double> source, int components = 1) const;

  std::size_t empty_target_count() const { return empty_targets_.size(); }
  const std::vector<std::size_t>& empty_target_indices() const { return empty_targets_; }
  std::size_t fallback_source_count() const { return fallback_sources_; }

 private:
  Constraint constraint_ = Constraint::consistent;
  Weights weights_;
  std::string source_mesh_;
  std::string target_mesh_;
  std::vector<std::size_t> empty_targets_;
  std::size_t fallback_sources_ = 0;
};

}  // namespace cosim::mapping
