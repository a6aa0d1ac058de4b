#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <functional>
#include <random>
#include <vector>

#include "acceleration/accelerator.hpp"

// A coupler's window loop in miniature, and the problems the tests iterate.
namespace cosim::acceleration::testing {

using FixedPointMap = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
using ConvergenceTest = std::function<bool(const Eigen::VectorXd& x, const Eigen::VectorXd& h)>;

struct WindowResult {
  bool converged = false;
  std::size_t evaluations = 0;       // of H
  std::size_t accelerate_calls = 0;  // iterations that did not converge
  Eigen::VectorXd x;                 // the converged iterate
};

// Iterates x^{k+1} = accelerate(x^k, H(x^k)) from x until `converged(x, H(x))`,
// evaluating H at most max_evaluations times; calls window_converged on
// success, and `after_accelerate` (if given) after each accelerate.
inline WindowResult iterate_window(Accelerator& accelerator, const FixedPointMap& map,
                                   Eigen::VectorXd x, const ConvergenceTest& converged,
                                   std::size_t max_evaluations,
                                   const std::function<void()>& after_accelerate = {}) {
  WindowResult result;
  Eigen::VectorXd next(x.size());
  while (result.evaluations < max_evaluations) {
    const Eigen::VectorXd h = map(x);
    ++result.evaluations;
    if (!h.allFinite()) break;
    if (converged(x, h)) {
      accelerator.window_converged({x.data(), static_cast<std::size_t>(x.size())},
                                   {h.data(), static_cast<std::size_t>(h.size())});
      result.converged = true;
      break;
    }
    accelerator.accelerate({x.data(), static_cast<std::size_t>(x.size())},
                           {h.data(), static_cast<std::size_t>(h.size())},
                           {next.data(), static_cast<std::size_t>(next.size())});
    ++result.accelerate_calls;
    if (after_accelerate) after_accelerate();
    x = next;
  }
  result.x = x;
  return result;
}

// Every block's residual is below `tolerance` relative to its part of H(x).
inline ConvergenceTest relative_per_block(std::vector<Block> blocks, double tolerance) {
  return
      [blocks = std::move(blocks), tolerance](const Eigen::VectorXd& x, const Eigen::VectorXd& h) {
        Eigen::Index offset = 0;
        for (const Block& block : blocks) {
          const auto size = static_cast<Eigen::Index>(block.size);
          const auto h_b = h.segment(offset, size);
          if ((h_b - x.segment(offset, size)).norm() > tolerance * h_b.norm()) return false;
          offset += size;
        }
        return true;
      };
}

inline Eigen::MatrixXd random_matrix(Eigen::Index n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Eigen::MatrixXd a(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i) a(i, j) = entry(rng);
  return a;
}

// S diag(eigenvalues) S^-1 with a random S: a non-symmetric matrix whose
// spectrum is known.
inline Eigen::MatrixXd random_matrix_with_eigenvalues(const Eigen::VectorXd& eigenvalues,
                                                      std::mt19937_64& rng) {
  const Eigen::MatrixXd s = random_matrix(eigenvalues.size(), rng);
  return s * eigenvalues.asDiagonal() * s.partialPivLu().inverse();
}

inline Eigen::VectorXd random_vector(Eigen::Index n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = entry(rng);
  return v;
}

}  // namespace cosim::acceleration::testing
