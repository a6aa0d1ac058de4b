#include "cosim/io/snapshot_writer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "cosim/error.hpp"
#include "hdf5_reader.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"
#include "xdmf_index_check.hpp"

namespace cosim {
namespace {

namespace fs = std::filesystem;
using testing::check_index;
using testing::Hdf5Reader;
using testing::ScratchDirectory;

std::vector<unsigned long long> dims_of(const Hdf5Reader& reader, const std::string& path) {
  const auto d = reader.dims(path);
  return {d.begin(), d.end()};
}

double pressure_at(const Vec3& x, double t) {
  return 1e5 + 3.0 * x[0] - 7.0 * x[1] + x[2] + t;
}

// HDF5 stamps objects with their creation time unless told not to; the
// writer tells it, so a run repeated (or continued from a checkpoint) can be
// compared with its original byte for byte.
TEST(SnapshotWriter, TheSameSnapshotWrittenAgainLaterHasTheSameBytes) {
  ScratchDirectory dir;
  const UniformGrid grid{2, {0.0, 0.0, 0.0}, {0.5, 0.25, 1.0}, {4, 3, 1}, GridLocation::cell};
  const Mesh mesh{"fluid", grid};
  std::vector<double> p(mesh.size());
  for (std::size_t e = 0; e < mesh.size(); ++e) p[e] = pressure_at(mesh.position(e), 0.5);
  const auto write_in = [&](const char* name) {
    SnapshotWriter writer(dir.path() / name, "fluid", mesh);
    writer.write(0.5, {{"p", {p, 1, "Pa"}}});
    return writer.snapshot_path(0);
  };
  const fs::path first = write_in("first");
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // HDF5's times are in seconds
  const fs::path second = write_in("second");
  const auto bytes = [](const fs::path& file) { return testing::read_text(file); };
  ASSERT_FALSE(bytes(first).empty());
  EXPECT_TRUE(bytes(first) == bytes(second)) << first << " and " << second << " differ";
}

TEST(SnapshotWriter, Cell2DGridRoundTripsAndIndexStaysValidAfterEverySnapshot) {
  ScratchDirectory dir;
  const UniformGrid grid{2, {1.0, 2.0, 0.0}, {0.5, 0.25, 1.0}, {4, 3, 1}, GridLocation::cell};
  const Mesh mesh{"fluid", grid};
  SnapshotWriter writer(dir.path(), "fluid", mesh);
  const std::vector<double> times{0.0, 0.1, 0.2};

  for (std::size_t s = 0; s < times.size(); ++s) {
    std::vector<double> p(mesh.size()), u(2 * mesh.size());
    for (std::size_t e = 0; e < mesh.size(); ++e) {
      p[e] = pressure_at(mesh.position(e), times[s]);
      u[2 * e] = static_cast<double>(e) + times[s];
      u[2 * e + 1] = -static_cast<double>(e);
    }
    writer.write(times[s], {{"p", {p, 1, "Pa"}}, {"u", {u, 2, "m/s"}}});
    const auto index = check_index(writer.index_path(), s + 1);
    EXPECT_EQ(index.times.back(), times[s]);
    EXPECT_EQ(index.heavy_items, static_cast<int>(2 * (s + 1)));
  }

  const auto index = check_index(writer.index_path(), 3);
  const auto& last = *index.grids.back();
  EXPECT_EQ(last.one("Topology").attribute("TopologyType"), "2DCoRectMesh");
  EXPECT_EQ(last.one("Topology").attribute("Dimensions"), "4 5");
  const auto origin_spacing = last.one("Geometry").all("DataItem");
  ASSERT_EQ(origin_spacing.size(), 2u);
  EXPECT_EQ(testing::parse_dims(origin_spacing[0]->text).size(), 2u);
  EXPECT_DOUBLE_EQ(std::stod(origin_spacing[0]->text), 2.0);   // origin y first
  EXPECT_DOUBLE_EQ(std::stod(origin_spacing[1]->text), 0.25);  // spacing y first
  for (const auto* attribute : last.all("Attribute")) {
    EXPECT_EQ(attribute->attribute("Center"), "Cell");
    EXPECT_EQ(attribute->attribute("AttributeType"),
              attribute->attribute("Name") == "p" ? "Scalar" : "Vector");
  }

  for (std::size_t s = 0; s < times.size(); ++s) {
    Hdf5Reader h5(writer.snapshot_path(s));
    EXPECT_EQ(h5.root_double("time"), times[s]);
    const auto p = h5.doubles("/fields/p");
    ASSERT_EQ(p.dims, (std::vector<hsize_t>{3, 4}));
    const auto u = h5.doubles("/fields/u");
    ASSERT_EQ(u.dims, (std::vector<hsize_t>{3, 4, 3}));
    double max_error = 0.0;
    for (std::int64_t j = 0; j < 3; ++j)
      for (std::int64_t i = 0; i < 4; ++i) {
        const std::size_t e = grid.flat(i, j);
        const std::size_t row_major = static_cast<std::size_t>(j * 4 + i);
        max_error = std::max(
            max_error, std::abs(p.values[row_major] - pressure_at(grid.position(e), times[s])));
        EXPECT_EQ(u.values[3 * row_major], static_cast<double>(e) + times[s]);
        EXPECT_EQ(u.values[3 * row_major + 1], -static_cast<double>(e));
        EXPECT_EQ(u.values[3 * row_major + 2], 0.0);
      }
    EXPECT_EQ(max_error, 0.0);
    EXPECT_EQ(h5.string_attribute("/fields/p", "unit"), "Pa");
  }
}

TEST(SnapshotWriter, Node3DGridStoresSlowestFirstWithNodeCentre) {
  ScratchDirectory dir;
  const UniformGrid grid{3, {0.0, -1.0, 0.5}, {0.1, 0.2, 0.3}, {2, 3, 4}, GridLocation::node};
  const Mesh mesh{"mpm_grid", grid};
  SnapshotWriter writer(dir.path(), "grid", mesh);
  std::vector<double> phi(mesh.size()), v(3 * mesh.size());
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    phi[e] = 0.001 * static_cast<double>(e);
    for (int c = 0; c < 3; ++c) v[3 * e + c] = mesh.position(e)[c];
  }
  for (int s = 0; s < 3; ++s) writer.write(0.5 * s, {{"phi_s", {phi, 1}}, {"velocity", {v, 3}}});

  const auto index = check_index(writer.index_path(), 3);
  const auto& topology = index.grids[0]->one("Topology");
  EXPECT_EQ(topology.attribute("TopologyType"), "3DCoRectMesh");
  EXPECT_EQ(topology.attribute("Dimensions"), "5 4 3");
  EXPECT_EQ(index.grids[0]->one("Geometry").attribute("GeometryType"), "ORIGIN_DXDYDZ");
  for (const auto* attribute : index.grids[2]->all("Attribute"))
    EXPECT_EQ(attribute->attribute("Center"), "Node");

  Hdf5Reader h5(writer.snapshot_path(2));
  const auto stored_phi = h5.doubles("/fields/phi_s");
  ASSERT_EQ(stored_phi.dims, (std::vector<hsize_t>{5, 4, 3}));
  EXPECT_EQ(stored_phi.values, phi);  // x fastest on both sides
  const auto stored_v = h5.doubles("/fields/velocity");
  ASSERT_EQ(stored_v.dims, (std::vector<hsize_t>{5, 4, 3, 3}));
  EXPECT_EQ(stored_v.values, v);
  EXPECT_DOUBLE_EQ(stored_v.values[3 * grid.flat(2, 3, 4) + 2], 0.5 + 4 * 0.3);
}

TEST(SnapshotWriter, NonUniformLineIsAPolylineThroughTheEdges) {
  ScratchDirectory dir;
  const std::vector<double> edges{0.0, 0.1, 0.3, 0.6, 1.0};
  const Mesh mesh{"channel", NonUniformLine{edges}};
  SnapshotWriter writer(dir.path(), "channel", mesh);
  for (int s = 0; s < 3; ++s) {
    std::vector<double> h(mesh.size());
    for (std::size_t c = 0; c < h.size(); ++c) h[c] = 1.0 + 0.1 * s + mesh.position(c)[0];
    writer.write(s * 0.25, {{"depth", {h, 1, "m"}}});
    check_index(writer.index_path(), static_cast<std::size_t>(s) + 1);
  }
  const auto index = check_index(writer.index_path(), 3);
  const auto& topology = index.grids[1]->one("Topology");
  EXPECT_EQ(topology.attribute("TopologyType"), "Polyline");
  EXPECT_EQ(topology.attribute("NodesPerElement"), "2");
  EXPECT_EQ(topology.attribute("NumberOfElements"), "4");
  EXPECT_EQ(index.grids[1]->one("Attribute").attribute("Center"), "Cell");

  Hdf5Reader geometry(dir / "channel_mesh.h5");
  const auto xyz = geometry.doubles("/geometry/xyz");
  ASSERT_EQ(xyz.dims, (std::vector<hsize_t>{5, 3}));
  for (std::size_t n = 0; n < edges.size(); ++n) {
    EXPECT_EQ(xyz.values[3 * n], edges[n]);
    EXPECT_EQ(xyz.values[3 * n + 1], 0.0);
  }
  const auto connectivity = geometry.integers("/topology/connectivity");
  ASSERT_EQ(connectivity.dims, (std::vector<hsize_t>{4, 2}));
  EXPECT_EQ(connectivity.values, (std::vector<std::int64_t>{0, 1, 1, 2, 2, 3, 3, 4}));

  Hdf5Reader last(writer.snapshot_path(2));
  EXPECT_FALSE(last.has("/geometry"));
  const auto depth = last.doubles("/fields/depth");
  EXPECT_DOUBLE_EQ(depth.values[3], 1.2 + 0.8);
}

TEST(SnapshotWriter, Uniform1DNodeGridIsAPolylineWithNodeValues) {
  ScratchDirectory dir;
  const Mesh mesh{"bed", UniformGrid{1, {2.0, 0, 0}, {0.5, 1, 1}, {6, 1, 1}, GridLocation::node}};
  SnapshotWriter writer(dir.path(), "bed", mesh);
  std::vector<double> b(mesh.size());
  for (std::size_t n = 0; n < b.size(); ++n) b[n] = -0.1 * mesh.position(n)[0];
  writer.write(0.0, {{"bed_elevation", {b, 1, "m"}}});
  const auto index = check_index(writer.index_path(), 1);
  EXPECT_EQ(index.grids[0]->one("Topology").attribute("NumberOfElements"), "6");
  EXPECT_EQ(index.grids[0]->one("Attribute").attribute("Center"), "Node");
  EXPECT_EQ(index.grids[0]->one("Attribute").one("DataItem").attribute("Dimensions"), "7");
  Hdf5Reader geometry(dir / "bed_mesh.h5");
  EXPECT_DOUBLE_EQ(geometry.doubles("/geometry/xyz").values[3 * 6], 5.0);
  EXPECT_EQ(Hdf5Reader(writer.snapshot_path(0)).doubles("/fields/bed_elevation").values, b);
}

TEST(SnapshotWriter, MovingPointCloudStoresGeometryPerSnapshot) {
  ScratchDirectory dir;
  auto cloud_at = [](double t) {
    PointCloud cloud{2, {}, {}};
    for (int p = 0; p < 5; ++p) {
      cloud.positions.push_back(0.1 * p + t);
      cloud.positions.push_back(1.0 - 0.5 * t * t);
      cloud.volumes.push_back(1e-4);
    }
    return Mesh{"particles", cloud};
  };
  SnapshotWriter writer(dir.path(), "particles", cloud_at(0.0));
  for (int s = 0; s < 3; ++s) {
    const double t = 0.1 * s;
    const Mesh moved = cloud_at(t);
    std::vector<double> velocity(2 * moved.size());
    for (std::size_t p = 0; p < moved.size(); ++p) {
      velocity[2 * p] = 1.0;
      velocity[2 * p + 1] = -t;
    }
    std::vector<double> stress(6 * moved.size(), -1e3 * s);
    writer.write(t, moved, {{"velocity", {velocity, 2, "m/s"}}, {"stress", {stress, 6, "Pa"}}});
    check_index(writer.index_path(), static_cast<std::size_t>(s) + 1);
  }
  const auto index = check_index(writer.index_path(), 3);
  for (std::size_t s = 0; s < 3; ++s) {
    const auto& grid = *index.grids[s];
    EXPECT_EQ(grid.one("Topology").attribute("TopologyType"), "Polyvertex");
    const std::string geometry_item = grid.one("Geometry").one("DataItem").text;
    EXPECT_EQ(geometry_item, writer.snapshot_path(s).filename().string() + ":/geometry/xyz");
    for (const auto* attribute : grid.all("Attribute")) {
      EXPECT_EQ(attribute->attribute("Center"), "Node");
      EXPECT_EQ(attribute->attribute("AttributeType"),
                attribute->attribute("Name") == "stress" ? "Tensor6" : "Vector");
    }

    const double t = 0.1 * static_cast<double>(s);
    Hdf5Reader h5(writer.snapshot_path(s));
    const auto xyz = h5.doubles("/geometry/xyz");
    ASSERT_EQ(xyz.dims, (std::vector<hsize_t>{5, 3}));
    for (std::size_t p = 0; p < 5; ++p) {
      EXPECT_EQ(xyz.values[3 * p], 0.1 * static_cast<double>(p) + t);
      EXPECT_EQ(xyz.values[3 * p + 1], 1.0 - 0.5 * t * t);
      EXPECT_EQ(xyz.values[3 * p + 2], 0.0);
    }
    const auto velocity = h5.doubles("/fields/velocity");
    ASSERT_EQ(velocity.dims, (std::vector<hsize_t>{5, 3}));
    EXPECT_EQ(velocity.values[3 * 4 + 1], -t);
    EXPECT_EQ(dims_of(h5, "/fields/stress"), (std::vector<unsigned long long>{5, 6}));
  }
  EXPECT_FALSE(fs::exists(dir / "particles_mesh.h5"));
}

TEST(SnapshotWriter, StaticCellCloudSharesOneGeometryFile) {
  ScratchDirectory dir;
  const Mesh mesh{"foam", CellCloud{3, {0, 0, 0, 1, 0, 0, 0, 1, 0}, {1.0, 1.0, 1.0}}};
  SnapshotWriter writer(dir.path(), "foam", mesh);
  const std::vector<double> alpha{0.0, 0.5, 1.0}, strange(4 * 3, 2.0);
  writer.write(0.0, {{"alpha.water", {alpha, 1}}});
  writer.write(1.0, {{"alpha.water", {alpha, 1}}, {"four", {strange, 4}}});
  const auto index = check_index(writer.index_path(), 2);
  for (const auto* grid : index.grids)
    EXPECT_EQ(grid->one("Geometry").one("DataItem").text, "foam_mesh.h5:/geometry/xyz");
  const auto four = index.grids[1]->all("Attribute");
  ASSERT_EQ(four.size(), 2u);
  EXPECT_EQ(four[1]->attribute("AttributeType"), "Matrix");
  EXPECT_EQ(four[1]->one("DataItem").attribute("Dimensions"), "3 4");
}

TEST(SnapshotWriter, BadFieldLosesNothingAlreadyWritten) {
  ScratchDirectory dir;
  const Mesh mesh{"g", UniformGrid{2, {0, 0, 0}, {1, 1, 1}, {2, 2, 1}, GridLocation::cell}};
  SnapshotWriter writer(dir.path(), "g", mesh);
  const std::vector<double> good(4, 1.0), short_field(3, 1.0);
  writer.write(0.0, {{"p", {good, 1}}});
  writer.write(1.0, {{"p", {good, 1}}});
  try {
    writer.write(2.0, {{"p", {good, 1}}, {"bad", {short_field, 1}}});
    FAIL() << "a field of the wrong size was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'bad'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(writer.write(2.0, {{"a/b", {good, 1}}}), InputError);
  EXPECT_EQ(check_index(writer.index_path(), 2).times, (std::vector<double>{0.0, 1.0}));
  EXPECT_FALSE(fs::exists(writer.snapshot_path(2)));

  writer.write(2.0, {{"p", {good, 1}}});
  EXPECT_EQ(check_index(writer.index_path(), 3).times.back(), 2.0);
}

TEST(SnapshotWriter, Hdf5FailureBecomesCosimErrorAndKeepsTheIndex) {
  ScratchDirectory dir;
  const Mesh mesh{"g", UniformGrid{2, {0, 0, 0}, {1, 1, 1}, {2, 2, 1}, GridLocation::cell}};
  SnapshotWriter writer(dir.path(), "g", mesh);
  const std::vector<double> p(4, 1.0);
  writer.write(0.0, {{"p", {p, 1}}});
  fs::create_directory(dir / ".g_000001.h5.tmp");  // H5Fcreate cannot truncate a directory
  try {
    writer.write(1.0, {{"p", {p, 1}}});
    FAIL() << "HDF5 failure not reported";
  } catch (const Error& e) {
    const std::string message = e.what();
    std::cout << "reported: " << message << "\n";
    EXPECT_NE(message.find("HDF5"), std::string::npos);
    EXPECT_NE(message.find("g_000001.h5"), std::string::npos);
  }
  EXPECT_EQ(check_index(writer.index_path(), 1).times, (std::vector<double>{0.0}));
}

TEST(SnapshotWriter, RejectsInvalidMeshAndOutputPathThatIsAFile) {
  ScratchDirectory dir;
  EXPECT_THROW(SnapshotWriter(dir.path(), "x", Mesh{"x", NonUniformLine{{1.0, 0.0}}}), InputError);
  std::ofstream(dir / "occupied") << "not a directory";
  const Mesh mesh{"g", UniformGrid{2, {0, 0, 0}, {1, 1, 1}, {2, 2, 1}, GridLocation::cell}};
  EXPECT_THROW(SnapshotWriter(dir / "occupied", "g", mesh), Error);
}

}  // namespace
}  // namespace cosim
