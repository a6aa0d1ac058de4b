#include "openfoam/io/restart_inertia.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "cosim/error.hpp"

namespace {

// A cell the interface crossed in the last step (air 1.2 -> 500 kg/m^3)
// keeps the air's density in its restart's inertia; a full one is unchanged.
TEST(RestartInertia, TheFluidFractionCarriesTheDensityOfTheStepBefore) {
  const std::vector<double> alphac{0.6, 1.0}, before{1.2, 1000.0}, end{500.0, 1000.0};
  const std::vector<double> lagged = openfoam::restart_fluid_fraction(alphac, before, end);
  ASSERT_EQ(lagged.size(), 2u);
  EXPECT_DOUBLE_EQ(lagged[0] * end[0], alphac[0] * before[0]);
  EXPECT_DOUBLE_EQ(lagged[1], 1.0);
}

TEST(RestartInertia, FieldsOfDifferentLengthsAreAnError) {
  const std::vector<double> alphac{1.0, 1.0}, before{1000.0}, end{1000.0, 1000.0};
  EXPECT_THROW(openfoam::restart_fluid_fraction(alphac, before, end), cosim::Error);
}

}  // namespace
