#include "ice/advection/limiter.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"

namespace {

using ice::limited_difference;
using ice::Limiter;

TEST(Limiter, ReadsEveryNameItWrites) {
  for (const std::string& name : ice::limiter_names()) {
    EXPECT_EQ(ice::to_string(ice::limiter_from_name(name)), name);
  }
  EXPECT_EQ(ice::limiter_from_name("van_leer"), Limiter::van_leer);
}

TEST(Limiter, RefusesAnUnknownNameWithASuggestion) {
  try {
    ice::limiter_from_name("vanleer");
    FAIL() << "no exception";
  } catch (const cosim::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("vanleer"), std::string::npos) << what;
    EXPECT_NE(what.find("van_leer"), std::string::npos) << what;
  }
}

TEST(Limiter, LimitsTheDifferenceOfACell) {
  // Smooth data: equal one-sided differences are kept.
  EXPECT_DOUBLE_EQ(limited_difference<Limiter::minmod>(0.3, 0.3), 0.3);
  EXPECT_DOUBLE_EQ(limited_difference<Limiter::van_leer>(0.3, 0.3), 0.3);
  // minmod takes the smaller, van Leer the harmonic mean 2ab / (a + b).
  EXPECT_DOUBLE_EQ(limited_difference<Limiter::minmod>(-1.0, -3.0), -1.0);
  EXPECT_DOUBLE_EQ(limited_difference<Limiter::van_leer>(-1.0, -3.0), -1.5);
  // At an extremum, or next to a flat side, the difference is zero.
  for (const auto& [a, b] : {std::pair{1.0, -2.0}, std::pair{0.0, 2.0}, std::pair{-1.0, 0.0}}) {
    EXPECT_EQ(limited_difference<Limiter::minmod>(a, b), 0.0);
    EXPECT_EQ(limited_difference<Limiter::van_leer>(a, b), 0.0);
  }
  EXPECT_EQ(limited_difference<Limiter::first_order>(0.3, 0.3), 0.0);
  // van Leer stays below twice the smaller side (the face value stays
  // between the neighbours).
  EXPECT_LE(limited_difference<Limiter::van_leer>(1.0, 100.0), 2.0);
}

}  // namespace
