#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "acceleration/accelerator.hpp"

// An AcceleratorState written and read back in one fixed order. The first
// scalar names the method, the second the size of x, so that a state is not
// restored into another method or onto other blocks.
namespace cosim::acceleration::detail {

class StateWriter {
 public:
  StateWriter(Method method, std::size_t size);

  void scalar(double value) { state_.scalars.push_back(value); }
  void count(std::size_t value) { scalar(static_cast<double>(value)); }
  void flag(bool value) { scalar(value ? 1.0 : 0.0); }
  void vector(const Eigen::VectorXd& values);
  void vector(const std::vector<double>& values) { state_.vectors.push_back(values); }

  AcceleratorState take() { return std::move(state_); }

 private:
  AcceleratorState state_;
};

// Throws std::invalid_argument, naming `what`, when the state lacks an entry,
// an entry has the wrong size, or entries are left over at finish().
class StateReader {
 public:
  StateReader(const AcceleratorState& state, Method method, std::size_t size);

  double scalar(const char* what);
  std::size_t count(const char* what);
  bool flag(const char* what);
  Eigen::VectorXd vector(const char* what, std::size_t size);
  std::vector<double> values(const char* what, std::size_t size);
  void finish() const;

 private:
  [[noreturn]] void fail(const std::string& why) const;

  const AcceleratorState& state_;
  std::size_t next_scalar_ = 0;
  std::size_t next_vector_ = 0;
};

}  // namespace cosim::acceleration::detail
