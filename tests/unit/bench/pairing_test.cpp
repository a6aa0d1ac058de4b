#include "bench/pairing.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "cosim/error.hpp"
#include "registered_backend.hpp"
#include "scratch_directory.hpp"

namespace cosim::bench {
namespace {

using cosim::testing::ScratchDirectory;
using testing::backend;

std::vector<std::string> exchanged(const YAML::Node& job) {
  std::vector<std::string> fields;
  for (const auto& e : job["exchange"]) fields.push_back(e["field"].as<std::string>());
  return fields;
}

bool has(const std::vector<std::string>& v, const std::string& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

Scenario porous_scenario(const std::string& drag) {
  Scenario s;
  s.name = "column";
  s.coupling = Coupling{};
  s.coupling->end_time = 1.0;
  s.coupling->window = 1e-3;
  s.coupling->soil_backend = registered_backends().soil();
  if (!drag.empty()) s.coupling->drag = YAML::Load(drag);
  s.coupling->optional_reads = {"solid_volume_flux"};
  return s;
}

const char* const soil_text =
    "kind: mpm_case\ndimension: 2\ncoupling:\n  exchange_grid: {factor: 2}\n  surface: {cells: "
    "[10]}\n";

TEST(Pairing, IceSendsThePressureForceAndSolvesTheDrag) {
  ScratchDirectory dir;
  const Scenario s =
      porous_scenario("{law: kozeny_carman, permeability: field, fluid_viscosity: 1e-3}");
  const PairedJob p =
      make_paired_job(backend("ice"), s, InputFile::read(dir.write("soil.yaml", soil_text)),
                      InputFile::read(dir.write("water.yaml", "kind: ice_case\n")), "column_ice",
                      "/in/soil.yaml", "/in/water.yaml");
  const YAML::Node job = p.job.root();
  EXPECT_EQ(job["participants"]["water"]["executable"].as<std::string>(), "ice_fluid");
  EXPECT_EQ(job["participants"]["water"]["config"].as<std::string>(), "/in/water.yaml");
  EXPECT_TRUE(job["participants"]["water"]["writes"]["pore_pressure_force"]);
  EXPECT_TRUE(job["participants"]["soil"]["writes"]["permeability"]);
  EXPECT_FALSE(job["participants"]["water"]["reads"]["solid_volume_flux"]);  // ICE does not read it
  EXPECT_EQ(job["momentum_exchange"]["solved_by"].as<std::string>(), "fluid");
  EXPECT_EQ(job["momentum_exchange"]["mesh"].as<std::string>(), "water.ice_cells");
  const auto fields = exchanged(job);
  EXPECT_TRUE(has(fields, "pore_pressure_force"));
  EXPECT_TRUE(has(fields, "solid_fraction"));
  // The soil keeps its exchange grid's own keys and drops the other pairing's block.
  EXPECT_EQ(p.soil.root()["coupling"]["exchange_grid"]["factor"].as<int>(), 2);
  EXPECT_FALSE(p.soil.root()["coupling"]["surface"]);
  EXPECT_EQ(p.fluid.root()["coupling"]["drag"].as<std::string>(), "ice");
}

TEST(Pairing, OpenFoamReadsTheOptionalVolumeFluxAndNoPressureForce) {
  ScratchDirectory dir;
  const Scenario s =
      porous_scenario("{law: kozeny_carman, grain_size: 1e-3, fluid_viscosity: 1e-3}");
  const PairedJob p = make_paired_job(
      backend("openfoam"), s, InputFile::read(dir.write("soil.yaml", soil_text)),
      InputFile::read(dir.write("water.yaml", "kind: openfoam_case\ndirectory: .\n")), "c", "s",
      "w");
  const YAML::Node job = p.job.root();
  EXPECT_EQ(job["participants"]["water"]["executable"].as<std::string>(), "openfoam_adapter");
  EXPECT_EQ(job["participants"]["water"]["meshes"]["openfoam_cells"]["kind"].as<std::string>(),
            "cell_cloud");  // a user's own case
  EXPECT_FALSE(has(exchanged(job), "pore_pressure_force"));
  EXPECT_TRUE(has(exchanged(job), "solid_volume_flux"));
  EXPECT_FALSE(job["participants"]["soil"]["writes"]["permeability"]);
}

TEST(Pairing, ShallowWaterExchangesTheBedAndItsTraction) {
  ScratchDirectory dir;
  Scenario s = porous_scenario("");
  const PairedJob p =
      make_paired_job(backend("swe"), s, InputFile::read(dir.write("soil.yaml", soil_text)),
                      InputFile::read(dir.write("water.yaml", "kind: swe_case\n")), "c", "s", "w");
  const YAML::Node job = p.job.root();
  EXPECT_EQ(job["participants"]["soil"]["meshes"]["mpm_surface"]["dim"].as<int>(), 1);
  EXPECT_EQ(job["participants"]["water"]["meshes"]["swe_cells"]["kind"].as<std::string>(),
            "nonuniform_line");
  EXPECT_EQ(exchanged(job), (std::vector<std::string>{"bed_elevation", "bed_traction"}));
  EXPECT_FALSE(job["momentum_exchange"]);
  EXPECT_FALSE(p.soil.root()["coupling"]["exchange_grid"]);
  EXPECT_EQ(p.fluid.root()["coupling"]["reads"][0].as<std::string>(), "bed_elevation");
}

TEST(Pairing, RefusesAPorousPairingWithoutADragLaw) {
  ScratchDirectory dir;
  EXPECT_THROW(
      make_paired_job(backend("ice"), porous_scenario(""),
                      InputFile::read(dir.write("soil.yaml", soil_text)),
                      InputFile::read(dir.write("water.yaml", "kind: ice_case\n")), "c", "s", "w"),
      InputError);
  EXPECT_THROW(
      make_paired_job(backend("swe"), porous_scenario(""),
                      InputFile::read(dir.write("bare.yaml", "kind: mpm_case\n")),
                      InputFile::read(dir.write("water.yaml", "kind: swe_case\n")), "c", "s", "w"),
      InputError);  // no surface grid for the bed
}

}  // namespace
}  // namespace cosim::bench
