#pragma once

#include <cstddef>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <vector>

// Fixed-point acceleration for implicit coupling: within a coupling window the
// coupler iterates x^{k+1} = accelerate(x^k, H(x^k)) until the residual
// r^k = H(x^k) - x^k is small, where x is the concatenation of the exchanged
// fields (the blocks) and H one pass of the solvers.
namespace cosim::acceleration {

// One field's slice of x; the blocks lie in x one after the other, in order.
struct Block {
  std::string name;
  std::size_t size;
  // The block's convergence limits (0: not given), for the `convergence`
  // preconditioner: converged when ||r_b|| <= relative ||H_b||, or <= absolute,
  // or <= residual_relative times the window's first ||r_b||.
  double relative = 0.0;
  double absolute = 0.0;
  double residual_relative = 0.0;
};

enum class Method { constant, aitken, iqn_ils, iqn_imvj };

// How IQN-ILS removes (nearly) linearly dependent columns from its least
// squares system (qr_filter.hpp).
enum class Filter { none, qr1, qr2 };

// Per-block weights of the residuals in IQN-ILS's least squares system
// (preconditioner.hpp).
enum class Preconditioner { none, value, residual_sum, convergence };

struct AccelerationSpec {
  Method method = Method::iqn_ils;
  // constant: omega, in (0, 2); aitken: the initial omega, in (0, 1]; IQN-ILS:
  // the omega of an iteration without columns, in (0, 1].
  double relaxation = 0.5;
  // IQN-ILS: most columns kept in V and W, the oldest dropped first.
  std::size_t max_columns = 100;
  // IQN-ILS: the columns of the last N converged windows are kept for the next
  // windows (0: each window starts without columns); IQN-IMVJ: the Jacobian
  // updates of the last N converged windows (multi_vector_jacobian.hpp).
  std::size_t reuse_windows = 8;
  Filter filter = Filter::qr2;
  // The filter's threshold, in (0, 1); unused with Filter::none.
  double filter_limit = 1e-2;
  Preconditioner preconditioner = Preconditioner::residual_sum;
  // After this many converged windows the preconditioner's weights stop
  // changing (0: never frozen).
  std::size_t freeze_preconditioner_after = 0;
};

// Everything an accelerator needs to resume bit for bit, for checkpoints; the
// layout belongs to the method that wrote it.
struct AcceleratorState {
  std::vector<double> scalars;
  std::vector<std::vector<double>> vectors;
};

class Accelerator {
 public:
  virtual ~Accelerator() = default;

  // x: the iterate that was given to the solvers (x^k); h: their answer
  // H(x^k); next: x^{k+1}, which may be the same memory as x or h. Called for
  // every iteration that did not converge. Throws std::invalid_argument when a
  // size differs from the blocks' total.
  virtual void accelerate(std::span<const double> x, std::span<const double> h,
                          std::span<double> next) = 0;

  // The window converged with this last pair (x, h): keep what the next window
  // reuses, reset the window's own history.
  virtual void window_converged(std::span<const double> x, std::span<const double> h) = 0;

  virtual AcceleratorState state() const = 0;
  // Throws std::invalid_argument for a state another method or other blocks
  // wrote.
  virtual void restore(const AcceleratorState& s) = 0;

  // IQN-ILS: the columns currently in V and W.
  virtual std::size_t columns() const { return 0; }
};

// Throws std::invalid_argument, naming the setting, for an invalid spec or
// blocks.
std::unique_ptr<Accelerator> make_accelerator(const AccelerationSpec& spec,
                                              std::vector<Block> blocks);

inline std::size_t total_size(const std::vector<Block>& blocks) {
  return std::accumulate(blocks.begin(), blocks.end(), std::size_t{0},
                         [](std::size_t sum, const Block& b) { return sum + b.size; });
}

}  // namespace cosim::acceleration
