#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "acceleration/accelerator.hpp"

namespace cosim::acceleration {
namespace {

Eigen::Vector2d h_of(const Eigen::Vector2d& x) {
  return {1.0 - 0.8 * x(0) + 0.5 * std::cos(x(1)), 0.3 * x(0) * x(0) - 1.2 * x(1) + 0.4};
}

// omega_k = -omega_{k-1} (r^{k-1} . (r^k - r^{k-1})) / ||r^k - r^{k-1}||^2
double aitken_factor(double previous_omega, const Eigen::Vector2d& previous_residual,
                     const Eigen::Vector2d& residual) {
  const Eigen::Vector2d change = residual - previous_residual;
  return -previous_omega * previous_residual.dot(change) / change.squaredNorm();
}

TEST(Aitken, ThreeIterationsMatchTheFactorsComputedByHand) {
  const double initial_omega = 0.7;
  auto aitken = make_accelerator({.method = Method::aitken, .relaxation = initial_omega},
                                 {{"a", 1}, {"b", 1}});
  const auto accelerate = [&](const Eigen::Vector2d& x) {
    const Eigen::Vector2d h = h_of(x);
    Eigen::Vector2d next;
    aitken->accelerate({x.data(), 2}, {h.data(), 2}, {next.data(), 2});
    return next;
  };

  const Eigen::Vector2d x0(1.0, 2.0);
  const Eigen::Vector2d r0 = h_of(x0) - x0;
  const Eigen::Vector2d x1 = x0 + initial_omega * r0;
  const Eigen::Vector2d r1 = h_of(x1) - x1;
  const double omega2 = aitken_factor(initial_omega, r0, r1);
  const Eigen::Vector2d x2 = x1 + omega2 * r1;
  const Eigen::Vector2d r2 = h_of(x2) - x2;
  const double omega3 = aitken_factor(omega2, r1, r2);
  const Eigen::Vector2d x3 = x2 + omega3 * r2;
  std::printf("Aitken factors by hand: %.6f %.6f %.6f\n", initial_omega, omega2, omega3);

  const Eigen::Vector2d next1 = accelerate(x0);
  const Eigen::Vector2d next2 = accelerate(next1);
  const Eigen::Vector2d next3 = accelerate(next2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(next1(i), x1(i), 1e-14);
    EXPECT_NEAR(next2(i), x2(i), 1e-14);
    EXPECT_NEAR(next3(i), x3(i), 1e-14);
  }

  // The next window starts with the last factor's sign and at most the
  // initial magnitude.
  const Eigen::Vector2d h3 = h_of(next3);
  aitken->window_converged({next3.data(), 2}, {h3.data(), 2});
  const double first_omega = std::copysign(std::min(initial_omega, std::abs(omega3)), omega3);
  const Eigen::Vector2d y0(0.5, -0.5);
  const Eigen::Vector2d expected = y0 + first_omega * (h_of(y0) - y0);
  const Eigen::Vector2d next = accelerate(y0);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(next(i), expected(i), 1e-14);
}

TEST(Aitken, AnUnchangedResidualFallsBackToTheInitialRelaxation) {
  auto aitken = make_accelerator({.method = Method::aitken, .relaxation = 0.3}, {{"a", 2}});
  const Eigen::Vector2d x(1.0, 1.0);
  const Eigen::Vector2d h(2.0, 0.0);
  Eigen::Vector2d next;
  aitken->accelerate({x.data(), 2}, {h.data(), 2}, {next.data(), 2});
  aitken->accelerate({x.data(), 2}, {h.data(), 2}, {next.data(), 2});
  EXPECT_TRUE(next.allFinite());
  EXPECT_DOUBLE_EQ(next(0), 1.3);
  EXPECT_DOUBLE_EQ(next(1), 0.7);
}

}  // namespace
}  // namespace cosim::acceleration
