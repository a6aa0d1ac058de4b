#include "swe/two_phase/solid_layer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

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

}  // namespace
}  // namespace swe
