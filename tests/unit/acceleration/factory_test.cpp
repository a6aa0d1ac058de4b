#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "acceleration/accelerator.hpp"

namespace cosim::acceleration {
namespace {

const std::vector<Block> blocks{{"p", 3}, {"u", 2}};

// The message of make_accelerator's std::invalid_argument, or "" if it
// accepted.
std::string rejection(const AccelerationSpec& spec, std::vector<Block> with_blocks = blocks) {
  try {
    make_accelerator(spec, std::move(with_blocks));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MakeAccelerator, AcceptsTheDefaultsOfEveryMethod) {
  for (const Method method : {Method::constant, Method::aitken, Method::iqn_ils, Method::iqn_imvj})
    EXPECT_EQ(rejection({.method = method}), "");
  EXPECT_EQ(rejection({.method = Method::constant, .relaxation = 1.5}), "");
  EXPECT_EQ(rejection({.method = Method::iqn_ils, .filter = Filter::none, .filter_limit = 0.0}),
            "");
}

TEST(MakeAccelerator, RejectsARelaxationOutsideTheMethodsRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double omega : {0.0, -0.5, 2.0, nan})
    EXPECT_THAT(rejection({.method = Method::constant, .relaxation = omega}),
                ::testing::HasSubstr("relaxation"))
        << omega;
  for (const Method method : {Method::aitken, Method::iqn_ils, Method::iqn_imvj})
    for (const double omega : {0.0, 1.5, nan})
      EXPECT_THAT(rejection({.method = method, .relaxation = omega}),
                  ::testing::HasSubstr("relaxation: "))
          << omega;
}

TEST(MakeAccelerator, RejectsIqnIlsWithoutColumnsOrWithAFilterLimitOutsideZeroOne) {
  EXPECT_THAT(rejection({.method = Method::iqn_ils, .max_columns = 0}),
              ::testing::HasSubstr("max_columns"));
  for (const Filter filter : {Filter::qr1, Filter::qr2})
    for (const double limit : {0.0, -1e-3, 1.0})
      EXPECT_THAT(rejection({.method = Method::iqn_ils, .filter = filter, .filter_limit = limit}),
                  ::testing::HasSubstr("filter_limit"))
          << limit;
}

TEST(MakeAccelerator, RejectsEmptyZeroSizedOrRepeatedBlocks) {
  EXPECT_THAT(rejection({}, {}), ::testing::HasSubstr("blocks"));
  EXPECT_THAT(rejection({}, {{"p", 3}, {"u", 0}}), ::testing::HasSubstr("block 'u' has size 0"));
  EXPECT_THAT(rejection({}, {{"p", 3}, {"p", 2}}), ::testing::HasSubstr("block 'p' appears twice"));
}

TEST(MakeAccelerator, AcceleratorsRejectVectorsOfTheWrongSize) {
  for (const Method method :
       {Method::constant, Method::aitken, Method::iqn_ils, Method::iqn_imvj}) {
    auto accelerator = make_accelerator({.method = method}, blocks);
    const std::vector<double> five(5, 1.0);
    const std::vector<double> four(4, 1.0);
    std::vector<double> next(5);
    EXPECT_THROW(accelerator->accelerate(four, five, next), std::invalid_argument);
    EXPECT_THROW(accelerator->accelerate(five, four, next), std::invalid_argument);
    EXPECT_THROW(accelerator->window_converged(five, four), std::invalid_argument);
  }
}

TEST(MakeAccelerator, AcceleratorsAllowTheNextIterateInTheMemoryOfX) {
  for (const Method method :
       {Method::constant, Method::aitken, Method::iqn_ils, Method::iqn_imvj}) {
    auto separate = make_accelerator({.method = method}, blocks);
    auto in_place = make_accelerator({.method = method}, blocks);
    std::vector<double> x{1e5, 2e5, 3e5, 0.01, 0.02};
    for (int k = 0; k < 4; ++k) {
      std::vector<double> h(5);
      for (std::size_t i = 0; i < 5; ++i) h[i] = 0.5 * x[(i + 1) % 5] + x[i] * (i < 3 ? 0.1 : 2.0);
      std::vector<double> next(5);
      separate->accelerate(x, h, next);
      in_place->accelerate(x, h, x);
      EXPECT_EQ(x, next) << "iteration " << k;
      x = next;
    }
  }
}

}  // namespace
}  // namespace cosim::acceleration
