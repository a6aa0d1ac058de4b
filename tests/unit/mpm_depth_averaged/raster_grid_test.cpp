#include "mpm/depth_averaged/raster_grid.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"
#include "scratch_directory.hpp"

namespace mpm {
namespace {

using cosim::testing::ScratchDirectory;

// z = x + 3 y - 9 on centres 10 m apart (the first at (5, 5)): bilinear
// interpolation reproduces it exactly.
const char* const plane_raster = R"(ncols 3
nrows 2
xllcorner 0
yllcorner 0
cellsize 10
NODATA_value -9999
41 51 61
11 21 31
)";

TEST(RasterGrid, ReadsAnEsriAsciiGridNorthRowFirstAndInterpolatesBilinearly) {
  ScratchDirectory dir;
  const RasterGrid r = RasterGrid::read_esri_ascii(dir.write("bed.asc", plane_raster));
  EXPECT_EQ(r.columns(), 3);
  EXPECT_EQ(r.rows(), 2);
  EXPECT_DOUBLE_EQ(r.at(0, 0), 11.0);  // south-west
  EXPECT_DOUBLE_EQ(r.at(2, 1), 61.0);  // north-east
  const Vec<2> x{12.0, 9.0};
  EXPECT_NEAR(r.value(x), x[0] + 3.0 * x[1] - 9.0, 1e-12);
  EXPECT_NEAR(r.gradient(x)[0], 1.0, 1e-12);
  EXPECT_NEAR(r.gradient(x)[1], 3.0, 1e-12);
  // Beyond the outermost centres the edge continues, flat.
  EXPECT_NEAR(r.value({-50.0, 5.0}), 11.0, 1e-12);
  EXPECT_EQ(r.gradient({-50.0, 10.0})[0], 0.0);
}

struct BadRaster {
  std::string from, to, message;
  int line;
};

class RasterRefuses : public ::testing::TestWithParam<BadRaster> {};

TEST_P(RasterRefuses, NamingTheFileAndLine) {
  ScratchDirectory dir;
  std::string text = plane_raster;
  text.replace(text.find(GetParam().from), GetParam().from.size(), GetParam().to);
  const auto file = dir.write("bed.asc", text);
  try {
    RasterGrid::read_esri_ascii(file);
    FAIL() << GetParam().message << ": accepted";
  } catch (const cosim::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bed.asc:" + std::to_string(GetParam().line)), std::string::npos) << what;
    EXPECT_NE(what.find(GetParam().message), std::string::npos) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Mistakes, RasterRefuses,
    ::testing::Values(BadRaster{"41 51 61", "41 -9999 61", "NODATA at row 1, column 2", 7},
                      BadRaster{"11 21 31\n", "11 21\n", "ends before row 2", 8},
                      BadRaster{"11 21 31\n", "11 21 31 7\n", "more values", 8},
                      BadRaster{"51", "5x1", "'5x1' is not a finite number", 7},
                      BadRaster{"cellsize 10", "cellsize 0", "must be positive", 5},
                      BadRaster{"cellsize", "cellsise", "unknown header key", 5},
                      BadRaster{"nrows 2\n", "", "missing from the header", 6}));

}  // namespace
}  // namespace mpm
