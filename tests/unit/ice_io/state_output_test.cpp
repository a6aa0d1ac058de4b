#include "ice/io/state_output.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "cosim/error.hpp"
#include "ice/eos/ideal_gas.hpp"
#include "scratch_directory.hpp"

namespace ice {
namespace {

IceSolver<2> two_gas_box() {
  const CellGrid<2> grid(CellGrid<2>::Point(0.0, 0.0), CellGrid<2>::Point(0.5, 0.25), {4, 2});
  FluidState<2> state;
  state.materials.resize(2);
  for (std::size_t m = 0; m < 2; ++m) {
    state.materials[m].bulk_density = make_cell_field(grid, m == 0 ? 0.3 : 0.9);
    state.materials[m].temperature = make_cell_field(grid, 300.0);
    state.materials[m].velocity[0] = make_cell_field(grid, m == 0 ? 1.0 : 3.0);
    state.materials[m].velocity[1] = make_cell_field(grid, 0.0);
  }
  std::vector<FluidMaterial> materials{{"a", std::make_shared<IdealGas>(287.0, 717.5), 0.0, 0.0},
                                       {"b", std::make_shared<IdealGas>(287.0, 717.5), 0.0, 0.0}};
  return IceSolver<2>(grid, materials, ExchangeCoefficients::none(2), {}, Eigen::Vector2d::Zero(),
                      state);
}

TEST(IceOutput, SnapshotHoldsMixtureAndPerMaterialFields) {
  const IceSolver<2> solver = two_gas_box();
  SnapshotFieldSet<2> set;
  const cosim::SnapshotFields& fields = set.fields(solver);
  for (const char* name : {"pressure", "density", "velocity", "volume_fraction_a", "bulk_density_b",
                           "density_a", "velocity_b", "temperature_a"}) {
    EXPECT_TRUE(fields.contains(name)) << name;
  }
  const cosim::FieldView& velocity = fields.at("velocity");
  ASSERT_EQ(velocity.components, 2);
  EXPECT_DOUBLE_EQ(velocity.values[0], (0.3 * 1.0 + 0.9 * 3.0) / 1.2);
  EXPECT_DOUBLE_EQ(fields.at("density").values[3], 1.2);
  const cosim::testing::ScratchDirectory scratch;
  const std::filesystem::path dir = scratch / "snapshot";
  cosim::SnapshotWriter writer(dir, "ice", cell_mesh(solver.grid(), "ice_cells"));
  writer.write(0.0, fields);
  EXPECT_TRUE(std::filesystem::exists(dir / "ice.xdmf"));
}

TEST(IceOutput, GaugesRecordTheCellHoldingThePoint) {
  const IceSolver<2> solver = two_gas_box();
  const cosim::testing::ScratchDirectory scratch;
  const std::filesystem::path file = scratch / "gauges.csv";
  {
    GaugeRecorder<2> gauges(file, {{"g", {1.9, 0.4, 0.0}}}, solver);
    gauges.record(0.0, solver);
    EXPECT_EQ(gauges.rows(), 1u);
  }
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "time [s],p_g [Pa],ux_g [m/s],uy_g [m/s],a_fraction_g [1],b_fraction_g [1]");
  std::string row;
  std::getline(in, row);
  EXPECT_NE(row.find(",2.5,0,0.25,0.75"), std::string::npos) << row;
  std::filesystem::remove(file);
  EXPECT_THROW(GaugeRecorder<2>(file, {{"far", {2.5, 0.1, 0.0}}}, solver), cosim::InputError);
}

// A wave gauge sums a material's volume fraction up the column through its
// point: b fills 0.75 of each cell, so its surface stands at 0.75 of the
// 0.5 m high column.
TEST(IceOutput, WaveGaugesRecordTheSurfaceOverTheirColumn) {
  const IceSolver<2> solver = two_gas_box();
  const cosim::testing::ScratchDirectory scratch;
  const std::filesystem::path file = scratch / "gauges.csv";
  {
    GaugeRecorder<2> gauges(file, {}, solver, {{"w", {1.1, 0.49, 0.0}, "b", 1}});
    const auto row = gauges.row(0.5, solver);
    ASSERT_EQ(row.size(), 2u);
    EXPECT_DOUBLE_EQ(row[1], 0.75 * 0.5);
  }
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "time [s],eta_w [m]");
  EXPECT_THROW(GaugeRecorder<2>(file, {}, solver, {{"w", {1.1, 0.0, 0.0}, "water", 1}}),
               cosim::InputError);
  EXPECT_THROW(GaugeRecorder<2>(file, {}, solver, {{"w", {2.6, 0.0, 0.0}, "b", 1}}),
               cosim::InputError);
}

}  // namespace
}  // namespace ice
