#include "ice/advection/specific_values.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace {

TEST(SpecificValues, DivideTheAdvectedDensityByTheBulkDensity) {
  const std::vector<double> rhobar{1000.0, 2.0, 1e-14, 0.0};
  const std::vector<double> momentum{1500.0, -4.0, 3e-14, 0.0};
  std::vector<double> u{9.0, 9.0, 9.0, 9.0};
  ice::specific_values(momentum, rhobar, 1e-12, ice::EmptyCell::keep_previous, u);
  EXPECT_DOUBLE_EQ(u[0], 1.5);
  EXPECT_DOUBLE_EQ(u[1], -2.0);
  EXPECT_EQ(u[2], 9.0);  // empty cells keep the previous value
  EXPECT_EQ(u[3], 9.0);
  ice::specific_values(momentum, rhobar, 1e-12, ice::EmptyCell::zero, u);
  EXPECT_EQ(u[2], 0.0);
  EXPECT_EQ(u[3], 0.0);
}

TEST(SpecificValues, RecoverTheTemperatureWithTheSpecificHeat) {
  // Tran et al., MPMICE, eq. 83 with c_v: T = (rhobar c_v T) / (rhobar c_v).
  const double c_v = 4186.0;
  const std::vector<double> rhobar{998.0};
  const std::vector<double> energy{998.0 * c_v * 293.15};
  std::vector<double> temperature{0.0};
  ice::specific_values(energy, rhobar, 1e-12, ice::EmptyCell::zero, temperature, c_v);
  EXPECT_NEAR(temperature[0], 293.15, 1e-12);
}

TEST(SpecificValues, RefuseMismatchedSizes) {
  const std::vector<double> rhobar{1.0, 1.0};
  const std::vector<double> quantity{1.0};
  std::vector<double> out(2);
  EXPECT_THROW(ice::specific_values(quantity, rhobar, 0.0, ice::EmptyCell::zero, out),
               std::invalid_argument);
  EXPECT_THROW(ice::specific_values(rhobar, rhobar, 0.0, ice::EmptyCell::zero, out, 0.0),
               std::invalid_argument);
}

}  // namespace
