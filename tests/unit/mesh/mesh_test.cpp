#include "cosim/mesh.hpp"

#include <gtest/gtest.h>

#include "cosim/error.hpp"

namespace cosim {
namespace {

TEST(UniformGrid, NodalControlVolumesSumToDomainVolume) {
  UniformGrid g{2, {0.0, 0.0, 0.0}, {0.5, 0.25, 1.0}, {4, 3, 1}, GridLocation::node};
  ASSERT_EQ(g.size(), 5u * 4u);
  double total = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i) total += g.control_volume(i);
  EXPECT_NEAR(total, 2.0 * 0.75, 1e-14);
}

TEST(UniformGrid, FlatIndexRoundTripsAndPositionsAreCellCentres) {
  UniformGrid g{3, {1.0, 2.0, 3.0}, {0.1, 0.2, 0.3}, {3, 4, 5}, GridLocation::cell};
  for (std::size_t f = 0; f < g.size(); ++f) {
    const Index3 ijk = g.unflat(f);
    EXPECT_EQ(g.flat(ijk[0], ijk[1], ijk[2]), f);
  }
  const Vec3 x = g.position(g.flat(2, 1, 4));
  EXPECT_NEAR(x[0], 1.0 + 2.5 * 0.1, 1e-14);
  EXPECT_NEAR(x[1], 2.0 + 1.5 * 0.2, 1e-14);
  EXPECT_NEAR(x[2], 3.0 + 4.5 * 0.3, 1e-14);
}

TEST(MeshValidation, RejectsBadGeometryNamingTheMesh) {
  Mesh line{"bed", NonUniformLine{{0.0, 1.0, 1.0}}};
  try {
    validate(line);
    FAIL() << "unsorted edges accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bed"), std::string::npos);
    EXPECT_EQ(e.code(), ExitCode::bad_input);
  }
  Mesh cloud{"particles", PointCloud{2, {0.0, 0.0, 1.0}, {1.0, 1.0}}};
  EXPECT_THROW(validate(cloud), InputError);
  Mesh grid{"g", UniformGrid{2, {0, 0, 0}, {1.0, -1.0, 1.0}, {2, 2, 1}, GridLocation::cell}};
  EXPECT_THROW(validate(grid), InputError);
  Mesh good{"g", UniformGrid{2, {0, 0, 0}, {1.0, 1.0, 1.0}, {2, 2, 1}, GridLocation::cell}};
  EXPECT_NO_THROW(validate(good));
  // Counts whose product overflows size(): 2^31 cubed wraps an int64.
  const std::int64_t n = std::int64_t{1} << 31;
  Mesh huge{"g", UniformGrid{3, {0, 0, 0}, {1.0, 1.0, 1.0}, {n, n, n}, GridLocation::cell}};
  EXPECT_THROW(validate(huge), InputError);
}

}  // namespace
}  // namespace cosim
