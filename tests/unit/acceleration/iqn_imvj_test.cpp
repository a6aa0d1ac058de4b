#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

#include "acceleration/accelerator.hpp"
#include "acceleration_test_support.hpp"

namespace cosim::acceleration {
namespace {

using testing::iterate_window;

// H(x) = A x + b_w, A with eigenvalues evenly spaced in [-1.5, 1.5] (the plain
// iteration diverges), b_w changing from window to window.
struct LinearWindows {
  Eigen::MatrixXd a;
  Eigen::VectorXd b0;
  Eigen::VectorXd b_change;

  static LinearWindows make(Eigen::Index n, unsigned seed) {
    std::mt19937_64 rng(seed);
    LinearWindows p;
    p.a = testing::random_matrix_with_eigenvalues(Eigen::VectorXd::LinSpaced(n, -1.5, 1.5), rng);
    p.b0 = testing::random_vector(n, rng);
    p.b_change = testing::random_vector(n, rng);
    return p;
  }
  Eigen::VectorXd b(int window) const { return b0 + 0.1 * window * b_change; }
};

AccelerationSpec spec_of(Method method, std::size_t reuse_windows, std::size_t max_columns) {
  AccelerationSpec spec;
  spec.method = method;
  spec.relaxation = 0.5;
  spec.reuse_windows = reuse_windows;
  spec.max_columns = max_columns;
  spec.filter = Filter::qr2;
  spec.filter_limit = 1e-6;
  spec.preconditioner = Preconditioner::none;
  return spec;
}

// Evaluations of H per window, each window to 1e-10 relative.
std::vector<std::size_t> evaluations_per_window(const AccelerationSpec& spec,
                                                const LinearWindows& problem, int windows) {
  const Eigen::Index n = problem.a.rows();
  auto accelerator = make_accelerator(spec, {{"x", static_cast<std::size_t>(n)}});
  const auto converged = testing::relative_per_block({{"x", static_cast<std::size_t>(n)}}, 1e-10);
  std::vector<std::size_t> evaluations;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (int w = 0; w < windows; ++w) {
    const Eigen::VectorXd b = problem.b(w);
    const auto map = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd { return problem.a * y + b; };
    const auto result = iterate_window(*accelerator, map, x, converged, 300);
    EXPECT_TRUE(result.converged) << "window " << w;
    evaluations.push_back(result.evaluations);
    x = result.x;
  }
  return evaluations;
}

void print(const char* name, const std::vector<std::size_t>& evaluations) {
  std::printf("%-34s evaluations per window:", name);
  for (const std::size_t e : evaluations) std::printf(" %zu", e);
  std::printf("\n");
}

// Within its first window IMVJ is IQN-ILS: at most n + 1 accelerations (n + 2
// evaluations) on a linear problem of size n. Those n independent columns
// make J exact, J = A (A - I)^-1, so the next window's first step,
// h - J r = (I - A)^-1 b, is its fixed point: one acceleration.
TEST(IqnImvj, AWindowWithNColumnsMakesTheJacobianExactForTheNext) {
  const LinearWindows problem = LinearWindows::make(10, 20261205);
  const auto imvj = evaluations_per_window(spec_of(Method::iqn_imvj, 8, 100), problem, 4);
  const auto ils = evaluations_per_window(spec_of(Method::iqn_ils, 0, 100), problem, 4);
  print("IQN-IMVJ", imvj);
  print("IQN-ILS, no reuse", ils);
  EXPECT_LE(imvj[0], 12u);
  EXPECT_EQ(imvj[0], ils[0]);
  for (std::size_t w = 1; w < imvj.size(); ++w) EXPECT_LE(imvj[w], 3u) << "window " << w;
}

// With few columns a window (3 of 10 directions), IQN-ILS's reused columns
// are capped as well, while IMVJ's Jacobian keeps what every window's columns
// taught it: over eight windows it needs fewer evaluations.
TEST(IqnImvj, TheJacobianKeepsWhatColumnsCappedPerWindowForget) {
  const LinearWindows problem = LinearWindows::make(10, 7);
  const auto imvj = evaluations_per_window(spec_of(Method::iqn_imvj, 8, 3), problem, 8);
  const auto ils = evaluations_per_window(spec_of(Method::iqn_ils, 8, 3), problem, 8);
  print("IQN-IMVJ, 3 columns", imvj);
  print("IQN-ILS, reuse 8, 3 columns", ils);
  const auto later = [](const std::vector<std::size_t>& e) {
    return std::accumulate(e.begin() + 4, e.end(), std::size_t{0});
  };
  EXPECT_LT(later(imvj), later(ils));
}

TEST(IqnImvj, ZeroReuseWindowsIsIqnIlsWithoutReuse) {
  const LinearWindows problem = LinearWindows::make(6, 11);
  EXPECT_EQ(evaluations_per_window(spec_of(Method::iqn_imvj, 0, 100), problem, 3),
            evaluations_per_window(spec_of(Method::iqn_ils, 0, 100), problem, 3));
}

}  // namespace
}  // namespace cosim::acceleration
