#pragma once

#include "mpm/core/tensor.hpp"

namespace mpm {

// Isotropic linear elasticity by its bulk modulus K and shear modulus G [Pa].
struct ElasticConstants {
  double bulk = 0.0;
  double shear = 0.0;

  static ElasticConstants from_youngs_poisson(double youngs_modulus, double poisson_ratio) {
    return {youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)),
            youngs_modulus / (2.0 * (1.0 + poisson_ratio))};
  }

  // Lame's first parameter lambda = K - 2G/3.
  double lame() const { return bulk - 2.0 / 3.0 * shear; }
  double youngs_modulus() const { return 9.0 * bulk * shear / (3.0 * bulk + shear); }
  double poisson_ratio() const { return (3.0 * bulk - 2.0 * shear) / (2.0 * (3.0 * bulk + shear)); }

  // Hooke's law: d sigma = lambda tr(d eps) I + 2 G d eps.
  Tensor stress_increment(const Tensor& strain_increment) const {
    return lame() * strain_increment.trace() * Tensor::Identity() + 2.0 * shear * strain_increment;
  }
  // Its inverse: d eps = dev(d sigma) / (2G) + tr(d sigma) / (9K) I.
  Tensor strain_increment(const Tensor& stress_increment) const {
    const double mean = stress_increment.trace() / 3.0;
    return (stress_increment - mean * Tensor::Identity()) / (2.0 * shear) +
           mean / (3.0 * bulk) * Tensor::Identity();
  }
};

}  // namespace mpm
