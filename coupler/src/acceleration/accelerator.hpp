#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

// Acceleration of the fixed-point iterations of an implicit coupling window
// (architecture.md §13): from the iterate x^k the participants ran and their
// answer H(x^k), the next iterate x^{k+1}. The vector is the concatenation of
// several fields (blocks), e.g. a pressure in Pa and a velocity in m/s.
namespace cosim::acceleration {

// One field's slice of the coupled vector, in order.
struct Block {
  std::string name;
  std::size_t size;
};

enum class Method { constant, aitken, iqn_ils };
enum class Filter { none, qr1, qr2 };
enum class Preconditioner { none, value, residual_sum };

struct AccelerationSpec {
  Method method = Method::iqn_ils;
  // constant: the factor; aitken: the first iteration's; iqn_ils: the
  // factor of an iteration with no column.
  double relaxation = 0.5;
  std::size_t max_columns = 100;  // iqn_ils: most columns kept, the oldest dropped first
  std::size_t reuse_windows = 8;  // iqn_ils: columns of the last N converged windows kept
  Filter filter = Filter::qr2;
  double filter_limit = 1e-2;
  Preconditioner preconditioner = Preconditioner::residual_sum;
  std::size_t freeze_preconditioner_after = 0;  // windows; 0: never frozen
};

// Everything an accelerator needs to go on bit for bit (a checkpoint).
struct AcceleratorState {
  std::vector<double> scalars;
  std::vector<std::vector<double>> vectors;
};

class Accelerator {
 public:
  virtual ~Accelerator() = default;
  // x: the iterate the participants ran (x^k); h: their answer H(x^k);
  // next: x^{k+1}. Called for every iteration that did not converge.
  virtual void accelerate(std::span<const double> x, std::span<const double> h,
                          std::span<double> next) = 0;
  // The window converged with this last pair: keep what the next window
  // reuses, forget the window's own history.
  virtual void window_converged(std::span<const double> x, std::span<const double> h) = 0;
  virtual AcceleratorState state() const = 0;
  virtual void restore(const AcceleratorState& s) = 0;
  virtual std::size_t columns() const { return 0; }
};

// Throws std::invalid_argument naming the setting when the spec is unusable.
std::unique_ptr<Accelerator> make_accelerator(const AccelerationSpec& spec,
                                              std::vector<Block> blocks);

}  // namespace cosim::acceleration
