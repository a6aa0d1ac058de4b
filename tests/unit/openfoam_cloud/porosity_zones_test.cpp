#include "openfoam/porosity/porosity_zones.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace openfoam {
namespace {

TEST(PorosityZones, AUniformColumnIsOneZoneWithItsCoefficient) {
  const std::vector<double> d{0.0, 4e8, 4e8, 4e8, 0.0};
  const auto zones = porosity_zones(d, 8);
  ASSERT_EQ(zones.size(), 1u);
  EXPECT_DOUBLE_EQ(zones[0].darcy, 4e8);
  EXPECT_LT(zones[0].lower, 4e8);
  EXPECT_GT(zones[0].upper, 4e8);
}

TEST(PorosityZones, NoSoilNoZone) {
  EXPECT_TRUE(porosity_zones(std::vector<double>{0.0, 0.0}, 8).empty());
}

TEST(PorosityZones, EveryCellFallsInOneZoneAndEachZoneIsWithinItsBinsRatio) {
  std::vector<double> d;
  for (int i = 0; i < 100; ++i) d.push_back(1e6 * std::pow(1e4, i / 99.0));
  const auto zones = porosity_zones(d, 4);
  ASSERT_EQ(zones.size(), 4u);
  for (double v : d) {
    int holders = 0;
    for (const auto& z : zones) holders += v >= z.lower && v < z.upper ? 1 : 0;
    EXPECT_EQ(holders, 1) << v;
  }
  for (const auto& z : zones) {
    EXPECT_GE(z.darcy, z.lower);
    EXPECT_LT(z.darcy, z.upper);
    EXPECT_NEAR(z.upper / z.lower, 10.0, 1e-6);  // 1e4 over four bins
  }
}

TEST(PorosityZones, TopoSetMakesAZonePerBinAndFvOptionsASourcePerZone) {
  const std::vector<PorosityZone> zones{{1.0, 2.0, 1.5}, {2.0, 4.0, 3.0}};
  const std::string topo = topo_set_dict(zones);
  EXPECT_NE(topo.find("source fieldToCell;"), std::string::npos) << topo;
  EXPECT_NE(topo.find("field soilDarcyCoefficient;"), std::string::npos) << topo;
  EXPECT_NE(topo.find("source setToCellZone;\n        set soil1;"), std::string::npos) << topo;
  const std::string options = porosity_fv_options(zones);
  EXPECT_NE(options.find("cellZone soil0;"), std::string::npos) << options;
  EXPECT_NE(options.find("d (3 3 3);"), std::string::npos) << options;
  EXPECT_NE(options.find("type DarcyForchheimer;"), std::string::npos) << options;
}

}  // namespace
}  // namespace openfoam
