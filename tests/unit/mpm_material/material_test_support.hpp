#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <memory>
#include <random>
#include <string>

#include "cosim/config/document.hpp"
#include "cosim/error.hpp"
#include "input_error.hpp"
#include "mpm/material/material_registry.hpp"

namespace mpm::testing {

inline std::unique_ptr<Material> material_from_yaml(const std::string& yaml) {
  const auto document = cosim::config::Document::load_string(yaml, "material.yaml");
  return make_material(document.root());
}

// The InputError that building `yaml` throws, printed as a user reads it.
inline cosim::InputError material_error(const std::string& yaml) {
  SCOPED_TRACE(yaml);
  return cosim::testing::input_error_from([&] { material_from_yaml(yaml); });
}

inline Tensor random_matrix(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Tensor t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t(i, j) = scale * u(rng);
  return t;
}

inline Tensor random_symmetric(std::mt19937& rng, double scale) {
  return sym(random_matrix(rng, scale));
}

inline Tensor random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

// Relative Frobenius distance.
inline double relative_difference(const Tensor& a, const Tensor& b) {
  return (a - b).norm() / std::max(1e-300, std::max(a.norm(), b.norm()));
}

}  // namespace mpm::testing
