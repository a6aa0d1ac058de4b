#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "acceleration/accelerator.hpp"
#include "acceleration_test_support.hpp"

namespace cosim::acceleration {
namespace {

using testing::iterate_window;

AccelerationSpec iqn_spec(Filter filter, double filter_limit, std::size_t reuse_windows) {
  AccelerationSpec spec;
  spec.method = Method::iqn_ils;
  spec.relaxation = 0.5;
  spec.filter = filter;
  spec.filter_limit = filter_limit;
  spec.reuse_windows = reuse_windows;
  spec.preconditioner = Preconditioner::none;
  return spec;
}

// H(x) = A x + b, A with eigenvalues evenly spaced in [-rho, rho].
struct LinearProblem {
  Eigen::MatrixXd a;
  Eigen::VectorXd b;

  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const { return a * x + b; }
  Eigen::VectorXd fixed_point() const {
    const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(a.rows(), a.cols());
    return (identity - a).fullPivLu().solve(b);
  }
};

LinearProblem random_linear_problem(Eigen::Index n, double spectral_radius, unsigned seed) {
  std::mt19937_64 rng(seed);
  LinearProblem problem;
  problem.a = testing::random_matrix_with_eigenvalues(
      Eigen::VectorXd::LinSpaced(n, -spectral_radius, spectral_radius), rng);
  problem.b = testing::random_vector(n, rng);
  return problem;
}

// IQN-ILS on a linear problem is GMRES in disguise (Haelterman et al., "On the
// similarities between the quasi-Newton inverse least squares method and
// GMRes"): x^{k+1} = H(y), where y minimises the linear residual over x^0 plus
// the span of the steps so far. After n independent steps y is the fixed
// point. The first accelerate has no column, so that is the (n+1)-th
// accelerate; one more evaluation of H confirms it. With spectral radius 1.5
// the plain iteration diverges.
TEST(IqnIls, SolvesALinearProblemOfSizeNWithAtMostNPlusOneAccelerations) {
  const Eigen::Index n = 10;
  const LinearProblem problem = random_linear_problem(n, 1.5, 20240611);
  const Eigen::VectorXd exact = problem.fixed_point();
  const auto at_fixed_point = [&](const Eigen::VectorXd& x, const Eigen::VectorXd&) {
    return (x - exact).norm() <= 1e-10 * exact.norm();
  };

  auto plain = make_accelerator({.method = Method::constant, .relaxation = 1.0}, {{"x", 10}});
  const auto diverging =
      iterate_window(*plain, problem, Eigen::VectorXd::Zero(n), at_fixed_point, 60);
  EXPECT_FALSE(diverging.converged);
  EXPECT_GT((diverging.x - exact).norm(), 1e3 * exact.norm());

  for (const auto& [filter, limit, name] :
       {std::tuple{Filter::none, 1e-2, "none"}, std::tuple{Filter::qr2, 1e-8, "qr2 1e-8"}}) {
    auto accelerator = make_accelerator(iqn_spec(filter, limit, 0), {{"x", 10}});
    const auto result =
        iterate_window(*accelerator, problem, Eigen::VectorXd::Zero(n), at_fixed_point, 40);
    std::printf("linear n = %ld, filter %s: %zu accelerations, %zu evaluations of H, error %.2e\n",
                static_cast<long>(n), name, result.accelerate_calls, result.evaluations,
                (result.x - exact).norm() / exact.norm());
    EXPECT_TRUE(result.converged) << name;
    EXPECT_LE(result.accelerate_calls, static_cast<std::size_t>(n) + 1) << name;
  }
}

// Three pairs whose residual differences are nearly parallel:
// r^2 - r^1 = 2 (r^1 - r^0) + 1e-10 e.
struct NearlyDependentPairs {
  std::vector<Eigen::VectorXd> x;
  std::vector<Eigen::VectorXd> h;

  NearlyDependentPairs() {
    const Eigen::Vector4d r0(1.0, 0.5, -0.2, 0.3);
    const Eigen::Vector4d step(0.2, -0.1, 0.4, 0.1);
    const Eigen::Vector4d r1 = r0 + step;
    const Eigen::Vector4d r2 = r1 + 2.0 * step + Eigen::Vector4d(0.0, 1e-10, 0.0, 0.0);
    x = {Eigen::Vector4d(0.0, 0.0, 0.0, 0.0), Eigen::Vector4d(0.3, -0.1, 0.2, 0.5),
         Eigen::Vector4d(0.1, 0.4, -0.3, 0.2)};
    h = {x[0] + r0, x[1] + r1, x[2] + r2};
  }

  Eigen::MatrixXd residual_differences() const {
    Eigen::MatrixXd v(4, 2);
    v.col(0) = (h[2] - x[2]) - (h[1] - x[1]);
    v.col(1) = (h[1] - x[1]) - (h[0] - x[0]);
    return v;
  }
};

Eigen::VectorXd accelerate_pairs(Accelerator& accelerator, const NearlyDependentPairs& pairs) {
  Eigen::VectorXd next(4);
  for (std::size_t k = 0; k < pairs.x.size(); ++k)
    accelerator.accelerate({pairs.x[k].data(), 4}, {pairs.h[k].data(), 4}, {next.data(), 4});
  return next;
}

TEST(IqnIls, FiltersDropTheOlderOfTwoNearlyParallelColumns) {
  const NearlyDependentPairs pairs;
  const Eigen::MatrixXd v = pairs.residual_differences();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(v);
  const double condition = svd.singularValues()(0) / svd.singularValues()(1);
  std::printf("condition number of V = %.3e\n", condition);
  EXPECT_GT(condition, 1e9);

  auto unfiltered = make_accelerator(iqn_spec(Filter::none, 1e-2, 0), {{"x", 4}});
  accelerate_pairs(*unfiltered, pairs);
  EXPECT_EQ(unfiltered->columns(), 2u);

  // With the newest column alone: c = -(v0 . r2) / ||v0||^2, x^3 = h^2 + c w0.
  const Eigen::VectorXd r2 = pairs.h[2] - pairs.x[2];
  const Eigen::VectorXd v0 = v.col(0);
  const Eigen::VectorXd w0 = pairs.h[2] - pairs.h[1];
  const Eigen::VectorXd expected = pairs.h[2] - (v0.dot(r2) / v0.squaredNorm()) * w0;

  for (const Filter filter : {Filter::qr1, Filter::qr2}) {
    auto filtered = make_accelerator(iqn_spec(filter, 1e-2, 0), {{"x", 4}});
    const Eigen::VectorXd next = accelerate_pairs(*filtered, pairs);
    EXPECT_EQ(filtered->columns(), 1u);
    EXPECT_TRUE(next.allFinite());
    EXPECT_LE((next - expected).norm(), 1e-12 * expected.norm());
  }
}

TEST(IqnIls, ReusedColumnsShortenTheNextWindowAndMaxColumnsCaps) {
  const Eigen::Index n = 10;
  LinearProblem problem = random_linear_problem(n, 1.5, 7);
  const Eigen::VectorXd b0 = problem.b;
  std::mt19937_64 rng(8);
  const Eigen::VectorXd b_change = testing::random_vector(n, rng);
  const auto converged = testing::relative_per_block({{"x", 10}}, 1e-10);

  struct Case {
    const char* name;
    std::size_t reuse_windows;
    std::size_t max_columns;
  };
  std::vector<std::vector<std::size_t>> evaluations;
  for (const Case& c :
       {Case{"no reuse", 0, 100}, Case{"reuse 4", 4, 100}, Case{"reuse 4, max 3 columns", 4, 3}}) {
    AccelerationSpec spec = iqn_spec(Filter::qr2, 1e-6, c.reuse_windows);
    spec.max_columns = c.max_columns;
    auto accelerator = make_accelerator(spec, {{"x", 10}});
    std::size_t most_columns = 0;
    const auto watch_columns = [&] {
      EXPECT_LE(accelerator->columns(), c.max_columns);
      most_columns = std::max(most_columns, accelerator->columns());
    };
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    evaluations.emplace_back();
    std::printf("%s: evaluations per window", c.name);
    for (int window = 0; window < 4; ++window) {
      problem.b = b0 + 0.1 * window * b_change;
      const auto result = iterate_window(*accelerator, problem, x, converged, 200, watch_columns);
      ASSERT_TRUE(result.converged) << c.name << " window " << window;
      EXPECT_LE(accelerator->columns(), c.max_columns);
      evaluations.back().push_back(result.evaluations);
      std::printf(" %zu", result.evaluations);
      x = result.x;
    }
    std::printf(", at most %zu columns\n", most_columns);
    if (c.max_columns == 3) {
      EXPECT_EQ(most_columns, 3u);
    }
  }
  const auto& without_reuse = evaluations[0];
  const auto& with_reuse = evaluations[1];
  EXPECT_LT(with_reuse[1], without_reuse[1]);
  for (std::size_t w = 1; w < with_reuse.size(); ++w) EXPECT_LT(with_reuse[w], without_reuse[w]);
}

}  // namespace
}  // namespace cosim::acceleration
