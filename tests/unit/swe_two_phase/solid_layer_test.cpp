#include "swe/two_phase/solid_layer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "input_error.hpp"

namespace swe {
namespace {

std::string error_of(const SolidLayer& layer, std::size_t cells) {
  return cosim::testing::input_error_message([&] { validate(layer, cells); });
}

TEST(SweSolidLayer, AnEmptyLayerIsValid) {
  const SolidLayer layer = empty_solid_layer(5, 2000.0);
  EXPECT_EQ(layer.size(), 5u);
  EXPECT_NO_THROW(validate(layer, 5));
}

TEST(SweSolidLayer, RefusesArraysOfAnotherSize) {
  SolidLayer layer = empty_solid_layer(5, 2000.0);
  layer.velocity_y.pop_back();
  const std::string message = error_of(layer, 5);
  EXPECT_NE(message.find("velocity_y has 4 values for 5 cells"), std::string::npos) << message;
  EXPECT_NE(error_of(empty_solid_layer(5, 2000.0), 6).find("depth has 5 values for 6 cells"),
            std::string::npos);
  layer = empty_solid_layer(5, 2000.0);
  layer.grain_size.assign(3, 1e-3);
  EXPECT_NE(error_of(layer, 5).find("grain_size has 3 values"), std::string::npos);
}

TEST(SweSolidLayer, NamesTheCellAndQuantityOfABadValue) {
  SolidLayer layer = empty_solid_layer(5, 2000.0);
  layer.depth[3] = -0.1;
  std::string message = error_of(layer, 5);
  EXPECT_NE(message.find("depth of cell 3"), std::string::npos) << message;
  layer = empty_solid_layer(5, 2000.0);
  layer.velocity_x[2] = std::numeric_limits<double>::quiet_NaN();
  message = error_of(layer, 5);
  EXPECT_NE(message.find("velocity_x of cell 2 must be finite"), std::string::npos) << message;
  layer = empty_solid_layer(5, 2000.0);
  layer.density[4] = 0.0;
  message = error_of(layer, 5);
  EXPECT_NE(message.find("density of cell 4"), std::string::npos) << message;
  layer = empty_solid_layer(5, 2000.0);
  layer.structured_share[1] = 1.5;
  message = error_of(layer, 5);
  EXPECT_NE(message.find("structured_share of cell 1 must be in [0, 1]"), std::string::npos)
      << message;
  layer = empty_solid_layer(5, 2000.0);
  layer.released_fluid_rate.assign(5, 0.0);
  layer.released_fluid_rate[0] = -1.0;
  message = error_of(layer, 5);
  EXPECT_NE(message.find("released_fluid_rate of cell 0"), std::string::npos) << message;
  layer = empty_solid_layer(5, 2000.0);
  layer.depth[0] = std::numeric_limits<double>::infinity();
  message = error_of(layer, 5);
  EXPECT_NE(message.find("depth of cell 0"), std::string::npos) << message;
}

TEST(SweSolidLayer, FromColumnsIsTheirDepthDensityVelocityAndStructuredShare) {
  // Two cells of 0.5 m^2: the first holds 0.25 m^3 of 2000 kg/m^3 moving at
  // (1, -2) m/s, 60 % still in blocks, which released 0.01 m^3 over a 0.1 s
  // window; the second holds nothing.
  const std::vector<double> volume{0.25, 0.0}, mass{500.0, 0.0}, momentum{500.0, -1000.0, 0.0, 0.0},
      structured{300.0, 0.0}, released{0.01, 0.0};
  const SolidLayer layer =
      layer_from_columns({volume, mass, momentum, structured, released}, 2, 0.5, 0.1, 2650.0);
  EXPECT_DOUBLE_EQ(layer.depth[0], 0.5);
  EXPECT_DOUBLE_EQ(layer.density[0], 2000.0);
  EXPECT_DOUBLE_EQ(layer.velocity_x[0], 1.0);
  EXPECT_DOUBLE_EQ(layer.velocity_y[0], -2.0);
  EXPECT_DOUBLE_EQ(layer.structured_share[0], 0.6);
  EXPECT_DOUBLE_EQ(layer.released_fluid_rate[0], 0.1);
  EXPECT_EQ(layer.depth[1], 0.0);
  EXPECT_EQ(layer.density[1], 2650.0);
  EXPECT_EQ(layer.velocity_x[1], 0.0);
  // Without released fluid the layer has none.
  EXPECT_TRUE(layer_from_columns({volume, mass, momentum, structured, {}}, 2, 0.5, 0.1, 2650.0)
                  .released_fluid_rate.empty());
}

TEST(SweSolidLayer, FromColumnsRefusesWhatAPeerMustNotSend) {
  const std::vector<double> volume{-0.25, 0.0}, mass{500.0, 0.0}, momentum{0.0, 0.0, 0.0, 0.0},
      structured{0.0, 0.0};
  std::string message = cosim::testing::input_error_message([&] {
    layer_from_columns({volume, mass, momentum, structured, {}}, 2, 0.5, 0.1, 2650.0);
  });
  EXPECT_NE(message.find("depth of cell 0"), std::string::npos) << message;
  message = cosim::testing::input_error_message([&] {
    layer_from_columns({mass, mass, std::span<const double>(momentum).first(3), structured, {}}, 2,
                       0.5, 0.1, 2650.0);
  });
  EXPECT_NE(message.find("column_momentum has 3 values for 2 cells"), std::string::npos) << message;
}

}  // namespace
}  // namespace swe
