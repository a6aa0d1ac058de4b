#include "openfoam/foam/control_dict.hpp"

#include <gtest/gtest.h>

namespace {

TEST(ControlDict, WritesTheDensityAloneOnlyAtTheStepItIsAskedFor) {
  openfoam::ControlSettings s{.application = "MPPICInterFoam",
                              .end_time = 0.01,
                              .time_step = 1e-3,
                              .write_every = 10,
                              .write_density_at = {},
                              .write_steps_between = {}};
  EXPECT_EQ(openfoam::control_dict(s).find("functions"), std::string::npos);
  s.write_density_at = 0.009;
  const std::string text = openfoam::control_dict(s);
  EXPECT_NE(text.find("type writeObjects;"), std::string::npos) << text;
  EXPECT_NE(text.find("objects (rho);"), std::string::npos) << text;
  EXPECT_NE(text.find("timeStart 0.0089999999999999993;"), std::string::npos) << text;
  EXPECT_NE(text.find("timeEnd 0.0089999999999999993;"), std::string::npos) << text;
}

TEST(ControlDict, WritesThePressureAndTheCloudsMomentumAtEveryStepOfTheWindowBeforeItsEnd) {
  const openfoam::ControlSettings s{.application = "MPPICInterFoam",
                                    .end_time = 0.004,
                                    .time_step = 1e-3,
                                    .write_every = 4,
                                    .write_density_at = 0.003,
                                    .write_steps_between = std::pair{0.001, 0.003}};
  const std::string text = openfoam::control_dict(s);
  EXPECT_NE(text.find("objects (rho);"), std::string::npos) << text;
  const auto pressure = text.find("exchangeWithinWindow");
  ASSERT_NE(pressure, std::string::npos) << text;
  EXPECT_NE(text.find("objects (p \"kinematicCloud:UTrans\");", pressure), std::string::npos)
      << text;
  EXPECT_NE(text.find("writeInterval 1;", pressure), std::string::npos) << text;
  EXPECT_NE(text.find("timeStart 0.001;", pressure), std::string::npos) << text;
  EXPECT_NE(text.find("timeEnd 0.0030000000000000001;", pressure), std::string::npos) << text;
}

}  // namespace
