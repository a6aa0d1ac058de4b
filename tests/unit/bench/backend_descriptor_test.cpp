#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "bench/backend_catalog.hpp"
#include "bench/suite.hpp"
#include "cosim/error.hpp"
#include "replaced_text.hpp"
#include "scratch_directory.hpp"

namespace cosim::bench {
namespace {

using cosim::testing::replaced;
using cosim::testing::ScratchDirectory;

// A fluid backend described in full; the cases below each spoil one line.
const char* const toy_descriptor = R"(kind: bench_backend
name: toy
executable: toy_fluid
case_kind: toy_case
outputs:
  snapshots: toy
  fields: {pressure: p, velocity_x: {dataset: u, component: 0}}
  gauge_file: gauges.csv
  gauge_columns: {pressure: "p_{gauge} [Pa]"}
fluid_pairing:
  kind: porous
  mesh: {name: toy_cells, kind: uniform_grid, dimension: same_as_soil}
  writes: [pore_pressure, momentum_exchange_impulse]
  reads: [solid_fraction, drag_coefficient]
  from_soil: [{field: solid_fraction}]
  to_soil: [{field: pore_pressure}]
  momentum_exchange: fluid
)";

TEST(BackendDescriptor, ReadsAFluidBackend) {
  ScratchDirectory dir;
  const BackendDescriptor d = load_backend_descriptor(dir.write("toy.yaml", toy_descriptor));
  EXPECT_EQ(d.name, "toy");
  EXPECT_EQ(d.executable, "toy_fluid");
  EXPECT_TRUE(d.has_standalone_case());
  EXPECT_TRUE(d.is_fluid());
  EXPECT_FALSE(d.is_soil());
  EXPECT_EQ(d.gauge_column("left", "pressure"), "p_left [Pa]");
  EXPECT_EQ(d.stored_field("velocity_x").dataset, "u");
  EXPECT_EQ(d.snapshot_base(), "toy");
  EXPECT_THROW(d.gauge_column("left", "depth"), Error);
  EXPECT_THROW(d.stored_field("depth"), Error);
  ASSERT_TRUE(d.fluid_pairing);
  EXPECT_EQ(d.fluid_pairing->mesh.name, "toy_cells");
  EXPECT_EQ(*d.fluid_pairing->momentum_exchange_solved_by, "fluid");
}

struct BadDescriptor {
  const char* what;
  const char* from;
  const char* to;
  const char* key;  // the key the error names
  int line;         // and its line
};

class BackendDescriptorRefuses : public ::testing::TestWithParam<BadDescriptor> {};

TEST_P(BackendDescriptorRefuses, AtTheKeyAndLine) {
  ScratchDirectory dir;
  const auto file = dir.write("toy.yaml", replaced(toy_descriptor, GetParam().from, GetParam().to));
  try {
    load_backend_descriptor(file);
    FAIL() << GetParam().what << " was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("toy.yaml:" + std::to_string(GetParam().line) + ":"), std::string::npos)
        << message;
    EXPECT_NE(message.find(GetParam().key), std::string::npos) << message;
    EXPECT_EQ(to_int(e.code()), 2);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Mistakes, BackendDescriptorRefuses,
    ::testing::Values(
        BadDescriptor{"another kind of file", "kind: bench_backend", "kind: bench_suite", "kind",
                      1},
        BadDescriptor{"no executable", "executable: toy_fluid\n", "", "executable", 1},
        BadDescriptor{"an unknown key", "case_kind: toy_case", "case_knd: toy_case", "case_knd", 4},
        BadDescriptor{"a field not in the catalogue", "writes: [pore_pressure,",
                      "writes: [pore_presure,", "fluid_pairing.writes", 13},
        BadDescriptor{"an unknown dimension rule", "dimension: same_as_soil}",
                      "dimension: sideways}", "fluid_pairing.mesh.dimension", 12},
        BadDescriptor{"a field sent but not written", "to_soil: [{field: pore_pressure}]",
                      "to_soil: [{field: solid_velocity}]", "fluid_pairing.to_soil", 16},
        BadDescriptor{"a gauge column without its gauge", "\"p_{gauge} [Pa]\"", "\"p [Pa]\"",
                      "outputs.gauge_columns.pressure", 9},
        BadDescriptor{"an unknown mapping", "{field: solid_fraction}",
                      "{field: solid_fraction, mapping: nearest}", "fluid_pairing.from_soil", 15}));

// The names CMake registered with cosim_register_backend (COSIM_BENCH_BACKENDS,
// comma-separated).
std::vector<std::string> registered_in_cmake() {
  std::vector<std::string> names;
  std::stringstream list(COSIM_REGISTERED_BACKENDS);
  for (std::string name; std::getline(list, name, ',');) names.push_back(name);
  std::sort(names.begin(), names.end());
  return names;
}

TEST(BackendCatalog, HoldsEveryRegisteredBackendAndNothingElse) {
  const BackendCatalog& catalog = registered_backends();
  EXPECT_EQ(catalog.names(), registered_in_cmake());
  ASSERT_NE(catalog.soil(), nullptr);
  EXPECT_EQ(catalog.soil()->name, "mpm");
  for (const auto& name : catalog.names()) {
    const BackendDescriptor& d = *catalog.find(name);
    if (d.is_fluid()) {
      EXPECT_TRUE(catalog.soil()->soil_pairings.count(d.fluid_pairing->kind)) << name;
    }
  }
}

// A suite's backends are the catalog's: a backend registered only in a
// catalog of its own is accepted there, and one it lacks is refused with the
// registered names.
TEST(BackendCatalog, ASuitesBackendsComeFromTheRegisteredDescriptors) {
  ScratchDirectory dir;
  dir.write("backends/toy.yaml", toy_descriptor);
  std::filesystem::copy_file(registered_backends().directory() / "mpm.yaml",
                             dir.path() / "backends" / "mpm.yaml");
  const BackendCatalog catalog = BackendCatalog::load(dir.path() / "backends");
  EXPECT_EQ(catalog.names(), (std::vector<std::string>{"mpm", "toy"}));
  dir.write("soil.yaml", "kind: mpm_case\nname: soil\ndimension: 2\n");
  dir.write("toy_water.yaml", "kind: toy_case\n");
  const char* const suite = R"(kind: bench_suite
name: toys
scenarios:
  - name: column
    soil: soil.yaml
    coupling: {end_time: 1.0, window: 0.1, drag: {law: constant, coefficient: 1.0}}
    backends:
      toy: {fluid: toy_water.yaml}
)";
  const Suite s = load_suite(dir.write("suite.yaml", suite), catalog);
  ASSERT_EQ(s.scenarios[0].backends.size(), 1u);
  EXPECT_EQ(s.scenarios[0].backends[0].backend->executable, "toy_fluid");
  EXPECT_EQ(s.scenarios[0].coupling->soil_backend->name, "mpm");
  try {
    load_suite(dir.write("ice_suite.yaml", replaced(suite, "toy: {fluid", "ice: {fluid")), catalog);
    FAIL() << "a backend the catalog lacks was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown backend 'ice'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mpm, toy"), std::string::npos) << e.what();
  }
}

TEST(BackendCatalog, RefusesADescriptorRegisteredUnderAnotherName) {
  ScratchDirectory dir;
  dir.write("backends/toy2.yaml", toy_descriptor);
  try {
    BackendCatalog::load(dir.path() / "backends");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("toy2.yaml"), std::string::npos) << e.what();
  }
}

TEST(BackendCatalog, RefusesAFluidWhosePairingNoSoilTakes) {
  ScratchDirectory dir;
  dir.write("backends/toy.yaml", toy_descriptor);
  EXPECT_THROW(BackendCatalog::load(dir.path() / "backends"), InputError);
}

}  // namespace
}  // namespace cosim::bench
