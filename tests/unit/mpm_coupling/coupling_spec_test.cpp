// The `coupling:` block of an mpm_case file.
#include "mpm/coupling/coupling_spec.hpp"

#include <gtest/gtest.h>

#include "cosim/config/document.hpp"
#include "cosim/error.hpp"
#include "mpm/case/load_case.hpp"
#include "mpm/coupling/field_names.hpp"
#include "text_files.hpp"

namespace mpm::coupling {
namespace {

CouplingSpec read(const std::string& yaml, int dimension = 2) {
  const auto doc = cosim::config::Document::load_string(yaml, "case.yaml");
  return read_coupling(doc.root()["coupling"], dimension);
}

TEST(MpmCouplingSpec, DefaultsWriteEveryPorousFieldAndReadPressureAndImpulse) {
  const CouplingSpec s = read("coupling:\n  exchange_grid: {}\n");
  ASSERT_TRUE(s.exchange_grid);
  EXPECT_FALSE(s.surface);
  EXPECT_EQ(s.exchange_grid->factor, 1);
  EXPECT_EQ(s.exchange_grid->writes.size(), 5u);
  EXPECT_TRUE(s.exchange_grid->reads_field(names::pore_pressure));
  EXPECT_TRUE(s.exchange_grid->reads_field(names::impulse));
  EXPECT_EQ(s.exchange_grid->held_density_factor, 1e30);
  EXPECT_TRUE(s.exchange_grid->hold_at_fixed_faces);
}

TEST(MpmCouplingSpec, ReadsEveryKey) {
  const CouplingSpec s = read(
      "coupling:\n"
      "  exchange_grid:\n"
      "    factor: 2\n"
      "    writes: [solid_fraction, solid_velocity, solid_bulk_density]\n"
      "    reads: [momentum_exchange_impulse]\n"
      "    held_density_factor: 1.0e20\n"
      "    hold_at_fixed_faces: false\n"
      "    held_bodies: [column]\n"
      "    initial_pore_pressure: 101325\n"
      "  surface:\n"
      "    cells: [40]\n"
      "    reads: []\n"
      "    bed_bodies: [seabed]\n");
  EXPECT_EQ(s.exchange_grid->factor, 2);
  EXPECT_FALSE(s.exchange_grid->writes_field(names::permeability));
  EXPECT_FALSE(s.exchange_grid->reads_field(names::pore_pressure));
  EXPECT_EQ(s.exchange_grid->held_density_factor, 1e20);
  EXPECT_FALSE(s.exchange_grid->hold_at_fixed_faces);
  EXPECT_EQ(s.exchange_grid->held_bodies, std::vector<std::string>{"column"});
  EXPECT_EQ(s.exchange_grid->initial_pore_pressure, 101325.0);
  ASSERT_TRUE(s.surface);
  EXPECT_EQ(s.surface->cells, std::vector<int>{40});
  EXPECT_TRUE(s.surface->writes_field(names::bed_elevation));
  EXPECT_TRUE(s.surface->reads.empty());
  EXPECT_EQ(s.surface->strips, 4);
}

TEST(MpmCouplingSpec, RefusesUnknownFieldsKeysAndAWrongSurfaceDimension) {
  EXPECT_THROW(read("coupling:\n  exchange_grid: {reads: [pore_presure]}\n"), cosim::InputError);
  EXPECT_THROW(read("coupling:\n  exchange_grid: {fator: 2}\n"), cosim::InputError);
  EXPECT_THROW(read("coupling:\n  surface: {cells: [10, 10]}\n", 2), cosim::InputError);
  EXPECT_THROW(read("coupling:\n  surface: {cells: [0, 10]}\n", 3), cosim::InputError);
  EXPECT_NO_THROW(read("coupling:\n  surface: {cells: [10, 10]}\n", 3));
  try {
    read("coupling:\n  surface:\n    cells: [10, 10]\n", 2);
  } catch (const cosim::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("coupling.surface.cells"), std::string::npos) << e.what();
  }
}

// The coupled case of configs/mpm_coupled: its `coupling` block reads, and
// the rest of the file is a valid mpm_case.
TEST(MpmCouplingSpec, TheShippedCoupledCaseIsValid) {
  const std::string file = std::string(COSIM_SOURCE_DIR) + "/configs/mpm_coupled/soil_column.yaml";
  const auto doc = cosim::config::Document::load_file(file);
  const CouplingSpec s = read_coupling(doc.root()["coupling"], 2);
  ASSERT_TRUE(s.exchange_grid);
  EXPECT_TRUE(s.exchange_grid->reads_field(names::pore_pressure));
  std::string without = cosim::testing::read_text(file);
  without = without.substr(0, without.find("coupling:"));
  const CaseDescription c = load_case_text(without, file);
  EXPECT_EQ(c.bodies.size(), 1u);
  EXPECT_TRUE(c.bodies[0].porous);
}

}  // namespace
}  // namespace mpm::coupling
