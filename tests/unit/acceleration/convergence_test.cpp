#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>

#include "acceleration/accelerator.hpp"
#include "acceleration_test_support.hpp"

namespace cosim::acceleration {
namespace {

using testing::iterate_window;

constexpr double pressure_scale = 1e5;   // Pa
constexpr double velocity_scale = 1e-2;  // m/s
constexpr Eigen::Index block_size = 6;

// A pressure block p ~ 1e5 Pa and a velocity block u ~ 1e-2 m/s coupled
// nonlinearly. In the scaled unknowns s_p = p / 1e5, s_u = u / 1e-2,
//   H_p = M_p s_p + c_p + 0.1 tanh(s_p) + 0.2 sin(s_u),
//   H_u = M_u s_u + c_u + 0.1 tanh(s_u) + 0.2 sin(s_p),
// where M_p and M_u are symmetric with eigenvalues evenly spread over
// [-1.4, 0.8]: constant relaxation with omega = 0.5 contracts by 0.9 at best.
// Unweighted, the velocity's residuals are 1e-7 of the pressure's and hardly
// enter IQN-ILS's least squares problem.
class TwoScaleProblem {
 public:
  TwoScaleProblem() {
    std::mt19937_64 rng(42);
    const auto block_matrix = [&rng] {
      const Eigen::HouseholderQR<Eigen::MatrixXd> qr(testing::random_matrix(block_size, rng));
      const Eigen::MatrixXd rotation = qr.householderQ();
      const Eigen::VectorXd eigenvalues = Eigen::VectorXd::LinSpaced(block_size, -1.4, 0.8);
      return Eigen::MatrixXd(rotation * eigenvalues.asDiagonal() * rotation.transpose());
    };
    const Eigen::Index n = 2 * block_size;
    linear_ = Eigen::MatrixXd::Zero(n, n);
    linear_.topLeftCorner(block_size, block_size) = block_matrix();
    linear_.bottomRightCorner(block_size, block_size) = block_matrix();
    offset_ = Eigen::VectorXd::Constant(n, 1.0) + 0.5 * testing::random_vector(n, rng);
    units_ = Eigen::VectorXd(n);
    units_ << Eigen::VectorXd::Constant(block_size, pressure_scale),
        Eigen::VectorXd::Constant(block_size, velocity_scale);
  }

  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const {
    const Eigen::VectorXd s = x.cwiseQuotient(units_);
    Eigen::VectorXd other_block(s.size());
    other_block << s.tail(block_size).array().sin().matrix(),
        s.head(block_size).array().sin().matrix();
    const Eigen::VectorXd h =
        linear_ * s + offset_ + 0.1 * s.array().tanh().matrix() + 0.2 * other_block;
    return h.cwiseProduct(units_);
  }

  Eigen::VectorXd initial_guess() const { return units_; }

 private:
  Eigen::MatrixXd linear_;
  Eigen::VectorXd offset_;
  Eigen::VectorXd units_;
};

const std::vector<Block> blocks{{"p", block_size}, {"u", block_size}};

testing::WindowResult solve(const AccelerationSpec& spec) {
  const TwoScaleProblem problem;
  auto accelerator = make_accelerator(spec, blocks);
  return iterate_window(*accelerator, problem, problem.initial_guess(),
                        testing::relative_per_block(blocks, 1e-8), 200);
}

std::size_t evaluations_or_limit(const testing::WindowResult& result) {
  return result.converged ? result.evaluations : 1000;
}

TEST(AccelerationConvergence, IqnIlsBeatsAitkenBeatsConstantOnATwoScaleNonlinearProblem) {
  const auto constant = solve({.method = Method::constant, .relaxation = 0.5});
  const auto aitken = solve({.method = Method::aitken, .relaxation = 0.5});
  const auto iqn = solve({.method = Method::iqn_ils,
                          .relaxation = 0.5,
                          .reuse_windows = 0,
                          .filter = Filter::qr2,
                          .filter_limit = 1e-2,
                          .preconditioner = Preconditioner::residual_sum});
  std::printf("evaluations to 1e-8 per block: constant(0.5) %zu%s, Aitken %zu, IQN-ILS %zu\n",
              constant.evaluations, constant.converged ? "" : " (not converged)",
              aitken.evaluations, iqn.evaluations);
  ASSERT_TRUE(iqn.converged);
  ASSERT_TRUE(aitken.converged);
  EXPECT_LT(iqn.evaluations, aitken.evaluations);
  EXPECT_LT(aitken.evaluations, evaluations_or_limit(constant));
}

TEST(AccelerationConvergence, ResidualSumPreconditionerNeedsNoMoreIterationsThanNone) {
  for (const Filter filter : {Filter::none, Filter::qr2}) {
    AccelerationSpec spec{.method = Method::iqn_ils,
                          .relaxation = 0.5,
                          .reuse_windows = 0,
                          .filter = filter,
                          .filter_limit = 1e-2};
    spec.preconditioner = Preconditioner::none;
    const auto unscaled = solve(spec);
    spec.preconditioner = Preconditioner::value;
    const auto value = solve(spec);
    spec.preconditioner = Preconditioner::residual_sum;
    const auto residual_sum = solve(spec);
    std::printf(
        "IQN-ILS filter %s, evaluations to 1e-8 per block: unscaled %zu%s, value %zu%s, "
        "residual-sum %zu%s\n",
        filter == Filter::none ? "none" : "qr2", unscaled.evaluations,
        unscaled.converged ? "" : " (not converged)", value.evaluations,
        value.converged ? "" : " (not converged)", residual_sum.evaluations,
        residual_sum.converged ? "" : " (not converged)");
    ASSERT_TRUE(residual_sum.converged);
    EXPECT_LE(residual_sum.evaluations, evaluations_or_limit(unscaled));
  }
}

}  // namespace
}  // namespace cosim::acceleration
