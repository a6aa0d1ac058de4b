#include "state_io.hpp"

#include <cmath>
#include <stdexcept>

namespace cosim::acceleration::detail {

StateWriter::StateWriter(Method method, std::size_t size) {
  scalar(static_cast<double>(static_cast<int>(method)));
  count(size);
}

void StateWriter::vector(const Eigen::VectorXd& values) {
  state_.vectors.emplace_back(values.begin(), values.end());
}

StateReader::StateReader(const AcceleratorState& state, Method method, std::size_t size)
    : state_(state) {
  if (scalar("method") != static_cast<double>(static_cast<int>(method)))
    fail("it was written by another acceleration method");
  if (count("size of x") != size) fail("it was written for blocks of another total size");
}

double StateReader::scalar(const char* what) {
  if (next_scalar_ >= state_.scalars.size()) fail(std::string("it lacks the ") + what);
  return state_.scalars[next_scalar_++];
}

std::size_t StateReader::count(const char* what) {
  const double value = scalar(what);
  if (!(value >= 0.0 && value < 9007199254740992.0) || std::floor(value) != value)
    fail(std::string("its ") + what + " is not a count");
  return static_cast<std::size_t>(value);
}

bool StateReader::flag(const char* what) {
  const double value = scalar(what);
  if (value != 0.0 && value != 1.0) fail(std::string("its ") + what + " is neither 0 nor 1");
  return value == 1.0;
}

std::vector<double> StateReader::values(const char* what, std::size_t size) {
  if (next_vector_ >= state_.vectors.size()) fail(std::string("it lacks the ") + what);
  const std::vector<double>& v = state_.vectors[next_vector_++];
  if (v.size() != size)
    fail(std::string("its ") + what + " has " + std::to_string(v.size()) + " values, not " +
         std::to_string(size));
  return v;
}

Eigen::VectorXd StateReader::vector(const char* what, std::size_t size) {
  const std::vector<double> v = values(what, size);
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

void StateReader::finish() const {
  if (next_scalar_ != state_.scalars.size() || next_vector_ != state_.vectors.size())
    fail("it has more entries than this method writes");
}

void StateReader::fail(const std::string& why) const {
  throw std::invalid_argument("acceleration: cannot restore the state: " + why);
}

}  // namespace cosim::acceleration::detail
