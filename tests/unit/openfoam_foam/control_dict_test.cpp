#include "openfoam/foam/control_dict.hpp"

#include <gtest/gtest.h>

namespace {

TEST(ControlDict, WritesTheDensityAloneOnlyAtTheStepItIsAskedFor) {
  openfoam::ControlSettings s{.application = "MPPICInterFoam", .end_time = 0.01,
                              .time_step = 1e-3, .write_every = 10, .write_density_at = {}};
  EXPECT_EQ(openfoam::control_dict(s).find("functions"), std::string::npos);
  s.write_density_at = 0.009;
  const std::string text = openfoam::control_dict(s);
  EXPECT_NE(text.find("type writeObjects;"), std::string::npos) << text;
  EXPECT_NE(text.find("objects (rho);"), std::string::npos) << text;
  EXPECT_NE(text.find("timeStart 0.0089999999999999993;"), std::string::npos) << text;
  EXPECT_NE(text.find("timeEnd 0.0089999999999999993;"), std::string::npos) << text;
}

}  // namespace
