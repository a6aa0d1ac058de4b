#include "acceleration/preconditioner.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

namespace cosim::acceleration {
namespace {

const std::vector<Block> blocks{{"p", 2}, {"u", 3}};

Eigen::VectorXd vector_of(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (const double value : values) v(i++) = value;
  return v;
}

TEST(PreconditionerWeights, ValueWeightsAreTheInverseNormsOfTheWindowsFirstIterate) {
  PreconditionerWeights weights(Preconditioner::value, blocks, 0);
  const Eigen::VectorXd zero_r = Eigen::VectorXd::Zero(5);
  weights.update(vector_of({3e5, 4e5, 0.0, 0.03, 0.04}), zero_r);
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 1.0 / 5e5);
  EXPECT_DOUBLE_EQ(weights.block_weights()[1], 1.0 / 0.05);

  weights.update(vector_of({1.0, 1.0, 1.0, 1.0, 1.0}), zero_r);
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 1.0 / 5e5);

  weights.window_converged();
  weights.update(vector_of({0.0, 2.0, 0.0, 0.0, 0.0}), zero_r);
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 0.5);
  EXPECT_DOUBLE_EQ(weights.block_weights()[1], 1.0);
}

TEST(PreconditionerWeights, ResidualSumWeightsByHand) {
  PreconditionerWeights weights(Preconditioner::residual_sum, blocks, 0);
  const Eigen::VectorXd x = Eigen::VectorXd::Ones(5);
  // ||r_p|| = 5e3, ||r_u|| = 0.5, ||r|| = sqrt(25e6 + 0.25)
  const Eigen::VectorXd r1 = vector_of({3e3, 4e3, 0.0, 0.3, 0.4});
  // ||r_p|| = 13, ||r_u|| = 0.2, ||r|| = sqrt(169 + 0.04)
  const Eigen::VectorXd r2 = vector_of({5.0, 12.0, 0.2, 0.0, 0.0});
  const double norm1 = std::sqrt(25e6 + 0.25);
  const double norm2 = std::sqrt(169.04);

  weights.update(x, r1);
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 1.0 / (5e3 / norm1));
  EXPECT_DOUBLE_EQ(weights.block_weights()[1], 1.0 / (0.5 / norm1));

  weights.update(x, r2);
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 1.0 / (5e3 / norm1 + 13.0 / norm2));
  EXPECT_DOUBLE_EQ(weights.block_weights()[1], 1.0 / (0.5 / norm1 + 0.2 / norm2));

  Eigen::VectorXd scaled = r2;
  weights.apply(scaled);
  EXPECT_DOUBLE_EQ(scaled(1), 12.0 * weights.block_weights()[0]);
  EXPECT_DOUBLE_EQ(scaled(2), 0.2 * weights.block_weights()[1]);

  // The next window sums afresh.
  weights.window_converged();
  weights.update(x, r2);
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 1.0 / (13.0 / norm2));
  EXPECT_DOUBLE_EQ(weights.block_weights()[1], 1.0 / (0.2 / norm2));
}

// Each block weighed by the inverse of the residual its convergence measure
// accepts, so that the least squares system minimises the residual in the
// measure the window is judged by.
TEST(PreconditionerWeights, ConvergenceWeightsAreTheInverseTolerances) {
  std::vector<Block> measured{{"p", 2}, {"u", 3}, {"f", 1}};
  measured[0].relative = 1e-3;  // ||r_p|| <= 1e-3 ||H_p||
  measured[1].relative = 1e-5;  // or, for u, the larger of
  measured[1].absolute = 1e-6;  // 1e-5 ||H_u|| and 1e-6
  PreconditionerWeights weights(Preconditioner::convergence, measured, 0);
  const Eigen::VectorXd x = vector_of({3e5, 4e5, 0.0, 0.3, 0.4, 2.0});
  const Eigen::VectorXd r = vector_of({0.0, 0.0, 0.0, 0.0, 0.0, 1.0});  // H_f = 3
  weights.update(x, r);
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 1.0 / (1e-3 * 5e5));
  EXPECT_DOUBLE_EQ(weights.block_weights()[1], 1.0 / (1e-5 * 0.5));
  // An unmeasured block: the inverse norm of its answer.
  EXPECT_DOUBLE_EQ(weights.block_weights()[2], 1.0 / 3.0);

  // Every iteration: the absolute floor takes over when u is small.
  weights.update(vector_of({3e5, 4e5, 0.0, 0.003, 0.004, 2.0}), r);
  EXPECT_DOUBLE_EQ(weights.block_weights()[1], 1.0 / 1e-6);
}

TEST(PreconditionerWeights, ConvergenceWeightsWithAResidualRelativeLimit) {
  std::vector<Block> measured{{"p", 1}};
  measured[0].residual_relative = 1e-2;  // ||r|| <= 1e-2 ||r|| of the window's first iteration
  PreconditionerWeights weights(Preconditioner::convergence, measured, 0);
  weights.update(vector_of({1.0}), vector_of({4.0}));
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 1.0 / 0.04);
  weights.update(vector_of({1.0}), vector_of({0.5}));
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 1.0 / 0.04);
  weights.window_converged();
  weights.update(vector_of({1.0}), vector_of({2.0}));
  EXPECT_DOUBLE_EQ(weights.block_weights()[0], 1.0 / 0.02);
}

TEST(PreconditionerWeights, FrozenWeightsNoLongerChange) {
  PreconditionerWeights weights(Preconditioner::residual_sum, blocks, 1);
  const Eigen::VectorXd x = Eigen::VectorXd::Ones(5);
  weights.update(x, vector_of({1.0, 0.0, 1.0, 0.0, 0.0}));
  const std::vector<double> after_first_window = weights.block_weights();
  EXPECT_FALSE(weights.frozen());
  weights.window_converged();
  EXPECT_TRUE(weights.frozen());
  weights.update(x, vector_of({1.0, 0.0, 0.0, 0.0, 0.0}));
  EXPECT_EQ(weights.block_weights(), after_first_window);
}

TEST(PreconditionerWeights, NoneWeighsEveryBlockOne) {
  PreconditionerWeights weights(Preconditioner::none, blocks, 0);
  weights.update(vector_of({3e5, 4e5, 0.0, 0.03, 0.04}), vector_of({1, 2, 3, 4, 5}));
  EXPECT_EQ(weights.block_weights(), (std::vector<double>{1.0, 1.0}));
}

}  // namespace
}  // namespace cosim::acceleration
