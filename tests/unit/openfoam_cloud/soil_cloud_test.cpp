#include "openfoam/cloud/soil_cloud.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cosim/io/files.hpp"
#include "openfoam/foam/field_file.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace openfoam {
namespace {

namespace fs = std::filesystem;
using cosim::testing::read_text;

SoilParcels two_parcels() {
  SoilParcels p;
  const double a[3] = {0.05, 0.05, 0.005}, b[3] = {0.15, 0.05, 0.005};
  const double ua[3] = {0.1, 0.0, 0.0}, ub[3] = {0.0, -0.2, 0.0};
  p.add(a, 0, ua, 1e-3, 1000.0);
  p.add(b, 1, ub, 2e-3, 50.0);
  return p;
}

TEST(SoilCloud, WritesEveryListOfTheParcelsWithOneEntryEach) {
  cosim::testing::ScratchDirectory dir;
  const fs::path time = dir / "0.25";
  fs::create_directories(time / "lagrangian" / cloud_name);
  cosim::write_file_atomically(time / "lagrangian" / cloud_name / "coordinates", "stale");
  write_soil_cloud(time, "0.25", two_parcels(), 2.65e6);
  const fs::path cloud = time / "lagrangian" / cloud_name;
  EXPECT_FALSE(fs::exists(cloud / "coordinates"));
  for (const char* f : {"d", "dTarget", "nParticle", "rho", "age", "tTurb"})
    EXPECT_EQ(read_field_list(cloud / f, FieldType::scalar).size(), 2u) << f;
  for (const char* f : {"U", "UTurb", "UCorrect"})
    EXPECT_EQ(read_field_list(cloud / f, FieldType::vector).size(), 6u) << f;
  for (const char* f : {"active", "typeId", "origId", "origProcId"})
    EXPECT_EQ(read_label_list(cloud / f).size(), 2u) << f;
  const auto u = read_field_list(cloud / "U", FieldType::vector);
  EXPECT_DOUBLE_EQ(u[0], 0.1);
  EXPECT_DOUBLE_EQ(u[4], -0.2);
  EXPECT_DOUBLE_EQ(read_field_list(cloud / "nParticle", FieldType::scalar)[1], 50.0);
  EXPECT_DOUBLE_EQ(read_field_list(cloud / "rho", FieldType::scalar)[0], 2.65e6);
  const std::string positions = read_text(cloud / "positions");
  EXPECT_NE(positions.find("Cloud<basicKinematicMPPICParcel>"), std::string::npos) << positions;
  EXPECT_NE(positions.find("(0.14999999999999999 0.050000000000000003 0.0050000000000000001) 1"),
            std::string::npos)
      << positions;
  const std::string properties =
      read_text(time / "uniform" / "lagrangian" / cloud_name / "cloudProperties");
  EXPECT_NE(properties.find("geometry positions;"), std::string::npos) << properties;
}

TEST(SoilCloud, NoParcelsRemovesTheCloud) {
  cosim::testing::ScratchDirectory dir;
  write_soil_cloud(dir / "0", "0", two_parcels(), 2.65e6);
  write_soil_cloud(dir / "0", "0", SoilParcels{}, 2.65e6);
  EXPECT_FALSE(fs::exists(dir / "0" / "lagrangian" / cloud_name));
  EXPECT_FALSE(fs::exists(dir / "0" / "uniform" / "lagrangian" / cloud_name));
}

}  // namespace
}  // namespace openfoam
