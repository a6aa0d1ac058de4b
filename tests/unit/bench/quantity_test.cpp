#include "bench/quantity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "cosim/io/snapshot_reader.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "registered_backend.hpp"
#include "scratch_directory.hpp"

namespace cosim::bench {
namespace {

using cosim::testing::ScratchDirectory;
using testing::backend;

QuantitySpec quantity(const std::string& kind, const std::string& yaml) {
  return {kind, YAML::Load(yaml), "metrics[0].quantity", {}};
}

// A 4 x 2 grid of 0.5 m cells whose water fills the bottom row and, at the
// snapshot's time, half the top row's first two cells.
void write_vof_snapshots(const std::filesystem::path& dir) {
  UniformGrid g;
  g.dim = 2;
  g.spacing = {0.5, 0.5, 1.0};
  g.cells = {4, 2, 1};
  SnapshotWriter writer(dir, "openfoam", Mesh{"openfoam_cells", g});
  std::vector<double> alpha{1, 1, 1, 1, 0, 0, 0, 0};
  std::vector<double> pressure{10, 11, 12, 13, 0, 1, 2, 3};
  writer.write(0.0, {{"alpha_water", {alpha, 1, "1"}}, {"pressure", {pressure, 1, "Pa"}}});
  alpha = {1, 1, 1, 1, 0.5, 0.5, 0, 0};
  writer.write(1.0, {{"alpha_water", {alpha, 1, "1"}}, {"pressure", {pressure, 1, "Pa"}}});
}

TEST(SnapshotReader, ReadsTimesFieldsAndTheGrid) {
  ScratchDirectory dir;
  write_vof_snapshots(dir.path());
  const SnapshotReader r(dir.path(), "openfoam");
  EXPECT_EQ(r.times(), (std::vector<double>{0.0, 1.0}));
  ASSERT_TRUE(r.grid().has_value());
  EXPECT_EQ(r.grid()->cells[0], 4);
  EXPECT_DOUBLE_EQ(r.grid()->spacing[1], 0.5);
  EXPECT_EQ(r.element_at(1, {1.2, 0.7, 0.0}), 6u);   // i = 2, j = 1
  EXPECT_EQ(r.element_at(1, {9.0, -3.0, 0.0}), 3u);  // clamped
  EXPECT_DOUBLE_EQ(r.field(1, "alpha_water").at(4), 0.5);
  EXPECT_FALSE(r.has_field(0, "velocity"));
  EXPECT_THROW(r.field(0, "velocity"), Error);
  EXPECT_THROW(SnapshotReader(dir.path(), "ice"), Error);
}

TEST(Quantity, AProfileSamplesTheSnapshotNearestItsTime) {
  ScratchDirectory dir;
  write_vof_snapshots(dir.path() / "out");
  const RunLayout run{&backend("openfoam"), false, dir.path() / "input", dir.path() / "out"};
  const Measurement m =
      measure(quantity("profile",
                       "{field: pressure, from: [0.25, 0.25], to: [1.75, 0.25], points: 4, "
                       "time: 0.98, offset: {openfoam: 10, ice: 0}}"),
              run);
  EXPECT_DOUBLE_EQ(m.time, 1.0);
  EXPECT_EQ(m.y, (std::vector<double>{0, 1, 2, 3}));
  EXPECT_EQ(m.abscissa, "x [m]");
  // A time no snapshot is near is refused, not measured elsewhere.
  EXPECT_THROW(
      measure(quantity("profile", "{field: pressure, from: [0, 0], to: [1, 0], time: 5}"), run),
      Error);
  const Measurement surface = measure(
      quantity("profile", "{field: free_surface, from: [0.25, 0], to: [1.75, 0], points: 4}"), run);
  EXPECT_EQ(surface.y, (std::vector<double>{0.75, 0.75, 0.5, 0.5}));
}

TEST(Quantity, TheWaterFrontAlongTheFloorInEverySnapshot) {
  ScratchDirectory dir;
  write_vof_snapshots(dir.path() / "out");
  const RunLayout run{&backend("openfoam"), false, dir.path() / "input", dir.path() / "out"};
  const Measurement m =
      measure(quantity("water_front", "{length_scale: 2.0, time_scale: 10, start: [-1, 0]}"), run);
  EXPECT_EQ(m.x, (std::vector<double>{-1.0, 0.0, 10.0}));
  EXPECT_EQ(m.y, (std::vector<double>{0.0, 1.0, 1.0}));  // the whole 2 m floor is wet
}

TEST(Quantity, AGaugeColumnInTheBackendsNamingReducedAsAsked) {
  ScratchDirectory dir;
  dir.write("out/water/gauges.csv",
            "time [s],p_probe [Pa],ux_probe [m/s]\n0,5,0\n0.5,7,1\n1.0,6,2\n");
  const RunLayout ice{&backend("ice"), true, dir.path() / "input", dir.path() / "out"};
  EXPECT_DOUBLE_EQ(*measure(quantity("gauge", "{name: probe, variable: pressure}"), ice).value, 6);
  EXPECT_DOUBLE_EQ(
      *measure(quantity("gauge", "{name: probe, variable: pressure, at: max}"), ice).value, 7);
  EXPECT_DOUBLE_EQ(
      *measure(quantity("gauge", "{name: probe, variable: pressure, at: 0.4, offset: 5}"), ice)
           .value,
      2);
  EXPECT_DOUBLE_EQ(*measure(quantity("gauge",
                                     "{name: probe, variable: velocity_x, at: first_above, "
                                     "threshold: 1.5}"),
                            ice)
                        .value,
                   1.0);
  const Measurement series = measure(
      quantity("gauge", "{name: probe, variable: velocity_x, at: series, divide_by: 2}"), ice);
  EXPECT_EQ(series.y, (std::vector<double>{0, 0.5, 1}));
  EXPECT_THROW(measure(quantity("gauge", "{name: probe, variable: depth}"), ice), Error);
  EXPECT_THROW(measure(quantity("gauge", "{name: other, variable: pressure}"), ice), Error);
}

TEST(Quantity, ANumberOfASummary) {
  ScratchDirectory dir;
  dir.write("out/summary.json",
            R"({"metrics": {"max_conservative_mapping_error": {"value": 3e-16}}})");
  const RunLayout run{&backend("coupler"), true, dir.path() / "input", dir.path() / "out"};
  EXPECT_DOUBLE_EQ(
      *measure(quantity("summary", "{value: /metrics/max_conservative_mapping_error/value}"), run)
           .value,
      3e-16);
  EXPECT_THROW(measure(quantity("summary", "{value: /metrics/none/value}"), run), Error);
}

}  // namespace
}  // namespace cosim::bench
