#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <vector>

#include "acceleration/accelerator.hpp"

namespace cosim::acceleration {
namespace {

const std::vector<Block> blocks{{"p", 3}, {"u", 2}};

Eigen::VectorXd h_of(const Eigen::VectorXd& x) {
  Eigen::VectorXd h(5);
  h << 2e5 - 0.9 * x(1) + 1e6 * x(3), 1e5 + 0.3 * x(0) - 2e6 * x(4), 5e4 + 0.5 * x(2),
      0.01 - 1e-7 * x(0) + 0.2 * std::sin(100.0 * x(4)), 0.02 - 0.5 * x(3) + 1e-8 * x(2);
  return h;
}

// Drives an accelerator along the iterates it produces, recording them.
struct Driver {
  Accelerator& accelerator;
  Eigen::VectorXd x;
  std::vector<Eigen::VectorXd> outputs;

  void iterate(int iterations) {
    for (int k = 0; k < iterations; ++k) {
      const Eigen::VectorXd h = h_of(x);
      Eigen::VectorXd next(5);
      accelerator.accelerate({x.data(), 5}, {h.data(), 5}, {next.data(), 5});
      outputs.push_back(next);
      x = next;
    }
  }
  void converge_window() {
    const Eigen::VectorXd h = h_of(x);
    accelerator.window_converged({x.data(), 5}, {h.data(), 5});
    x = h;
  }
};

void expect_bitwise_equal(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())), 0)
      << a.transpose() << "\n"
      << b.transpose();
}

class StateRoundTrip : public ::testing::TestWithParam<Method> {};

TEST_P(StateRoundTrip, RestoredAcceleratorContinuesBitForBit) {
  AccelerationSpec spec{.method = GetParam(), .relaxation = 0.4, .reuse_windows = 2};
  auto original = make_accelerator(spec, blocks);
  Eigen::VectorXd x0(5);
  x0 << 1e5, 2e5, 3e5, 0.01, 0.02;
  Driver run{*original, x0, {}};
  run.iterate(4);
  run.converge_window();
  run.iterate(3);
  const auto saved = original->state();
  const Eigen::VectorXd resume_from = run.x;
  run.iterate(2);
  if (GetParam() == Method::iqn_ils || GetParam() == Method::iqn_imvj) {
    EXPECT_GT(original->columns(), 0u);
  }

  auto restored = make_accelerator(spec, blocks);
  restored->restore(saved);
  Driver again{*restored, resume_from, {}};
  again.iterate(2);
  EXPECT_EQ(restored->columns(), original->columns());
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_TRUE(run.outputs[7 + k].allFinite());
    expect_bitwise_equal(again.outputs[k], run.outputs[7 + k]);
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, StateRoundTrip,
                         ::testing::Values(Method::constant, Method::aitken, Method::iqn_ils,
                                           Method::iqn_imvj),
                         [](const auto& test_info) {
                           switch (test_info.param) {
                             case Method::constant:
                               return "constant";
                             case Method::aitken:
                               return "aitken";
                             case Method::iqn_ils:
                               return "iqn_ils";
                             case Method::iqn_imvj:
                               return "iqn_imvj";
                           }
                           return "unknown";
                         });

TEST(StateRestore, RejectsTheStateOfAnotherMethodOrOtherBlocks) {
  auto aitken = make_accelerator({.method = Method::aitken}, blocks);
  auto iqn = make_accelerator({.method = Method::iqn_ils}, blocks);
  EXPECT_THROW(iqn->restore(aitken->state()), std::invalid_argument);
  auto imvj = make_accelerator({.method = Method::iqn_imvj}, blocks);
  EXPECT_THROW(imvj->restore(iqn->state()), std::invalid_argument);
  auto larger = make_accelerator({.method = Method::iqn_ils}, {{"p", 4}, {"u", 2}});
  EXPECT_THROW(larger->restore(iqn->state()), std::invalid_argument);
  auto truncated = iqn->state();
  truncated.vectors.pop_back();
  EXPECT_THROW(iqn->restore(truncated), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::acceleration
