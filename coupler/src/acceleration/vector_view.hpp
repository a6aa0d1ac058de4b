#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

// The coupler's spans seen as Eigen vectors, without copies.
namespace cosim::acceleration::detail {

inline Eigen::Map<const Eigen::VectorXd> as_eigen(std::span<const double> v) {
  return {v.data(), static_cast<Eigen::Index>(v.size())};
}

inline Eigen::Map<Eigen::VectorXd> as_eigen(std::span<double> v) {
  return {v.data(), static_cast<Eigen::Index>(v.size())};
}

inline void require_size(std::span<const double> v, std::size_t expected, const char* what) {
  if (v.size() != expected)
    throw std::invalid_argument("acceleration: " + std::string(what) + " has " +
                                std::to_string(v.size()) + " values, the blocks " +
                                std::to_string(expected));
}

}  // namespace cosim::acceleration::detail
