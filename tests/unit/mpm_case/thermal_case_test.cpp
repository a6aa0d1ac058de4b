// The thermal keys of a `kind: mpm_case` file: what they read, where their
// mistakes are reported, and what a thermal run writes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cosim/error.hpp"
#include "mpm/case/case_schema.hpp"
#include "mpm/case/load_case.hpp"
#include "mpm/io/run_driver.hpp"
#include "replaced_text.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace mpm {
namespace {

namespace fs = std::filesystem;
using cosim::testing::read_text;
using cosim::testing::replaced;
using ::testing::HasSubstr;

// A porous thermal strip between two held temperatures over a rigid hot
// plate that conducts (lines numbered for the located errors below).
const char* const thermal_case = R"(kind: mpm_case
dimension: 2
grid: {origin: [0, 0], upper: [1, 0.5], cells: [10, 5]}
time: {end_time: 0.02}
materials:
  sand: {type: linear_elastic, density: 2650, youngs_modulus: 1.0e6, poisson_ratio: 0.3, specific_heat: 835, thermal_conductivity: 0.4}
bodies:
  - name: strip
    material: sand
    temperature: 300
    geometry: {box: {min: [0, 0.1], max: [1, 0.3]}}
    porous: {porosity: 0.4, grain_size: 1.0e-3}
  - name: plate
    rigid: {motion: fixed}
    density: 7800
    specific_heat: 500
    thermal_conductivity: 40
    temperature: 350
    geometry: {box: {min: [0, 0], max: [1, 0.1]}}
thermal:
  x_min: {type: fixed_temperature, temperature: 310}
  x_max: {type: fixed_temperature, temperature: 290}
  y_max: {type: insulated}
probes:
  - {name: mid, body: strip, position: [0.5, 0.2]}
output: {every: 0.01}
threads: 1
)";

std::string error_of(const std::string& text) {
  try {
    load_case_text(text, "case.yaml");
  } catch (const cosim::InputError& e) {
    std::printf("    InputError: %s\n", e.what());
    EXPECT_EQ(e.code(), cosim::ExitCode::bad_input);
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(MpmThermalCase, ReadsEveryThermalKey) {
  const CaseDescription c = load_case_text(thermal_case, "case.yaml");
  ASSERT_TRUE(c.materials[0]->thermal().has_value());
  EXPECT_DOUBLE_EQ(c.materials[0]->thermal()->specific_heat, 835.0);
  EXPECT_DOUBLE_EQ(c.materials[0]->thermal()->conductivity, 0.4);
  EXPECT_DOUBLE_EQ(c.bodies[0].initial_temperature, 300.0);
  ASSERT_TRUE(c.bodies[1].thermal_override.has_value());
  EXPECT_DOUBLE_EQ(c.bodies[1].thermal_override->specific_heat, 500.0);
  EXPECT_DOUBLE_EQ(c.bodies[1].thermal_override->conductivity, 40.0);
  EXPECT_DOUBLE_EQ(c.bodies[1].initial_temperature, 350.0);
  EXPECT_EQ(thermal_properties(c, c.bodies[1]), &*c.bodies[1].thermal_override);
  EXPECT_TRUE(c.thermal.enabled);  // a body is thermal
  EXPECT_EQ(c.thermal.faces[0].kind, FaceTemperature::Kind::fixed);
  EXPECT_DOUBLE_EQ(c.thermal.faces[0].temperature, 310.0);
  EXPECT_DOUBLE_EQ(c.thermal.faces[1].temperature, 290.0);
  EXPECT_EQ(c.thermal.faces[2].kind, FaceTemperature::Kind::insulated);
  EXPECT_EQ(c.thermal.faces[3].kind, FaceTemperature::Kind::insulated);
}

TEST(MpmThermalCase, DefaultsKeepOldCasesMechanical) {
  std::string text = replaced(thermal_case, ", specific_heat: 835, thermal_conductivity: 0.4", "");
  text = replaced(text, "    specific_heat: 500\n    thermal_conductivity: 40\n", "");
  text = replaced(text, "    temperature: 300\n", "");
  text = text.substr(0, text.find("thermal:\n")) + text.substr(text.find("probes:"));
  const CaseDescription c = load_case_text(text, "case.yaml");
  EXPECT_FALSE(c.thermal.enabled);
  EXPECT_FALSE(has_thermal_body(c));
  EXPECT_DOUBLE_EQ(c.bodies[0].initial_temperature, 293.15);
  // enabled: false switches a thermal case off.
  const CaseDescription off = load_case_text(
      replaced(thermal_case, "thermal:\n", "thermal:\n  enabled: false\n"), "case.yaml");
  EXPECT_FALSE(off.thermal.enabled);
}

TEST(MpmThermalCase, MistakesAreLocatedAtTheirKeys) {
  EXPECT_THAT(error_of(replaced(thermal_case, "specific_heat: 835", "specific_heat: -835")),
              HasSubstr("case.yaml:6:"));
  EXPECT_THAT(error_of(replaced(thermal_case, "specific_heat: 835", "specific_heat: -835")),
              HasSubstr("key 'materials.sand.specific_heat'"));
  EXPECT_THAT(
      error_of(replaced(thermal_case, "thermal_conductivity: 0.4", "thermal_conductivity: -1")),
      HasSubstr("key 'materials.sand.thermal_conductivity'"));
  EXPECT_THAT(
      error_of(replaced(thermal_case, "specific_heat: 835, ", "")),
      HasSubstr(
          "key 'materials.sand.thermal_conductivity': thermal_conductivity needs specific_heat"));
  EXPECT_THAT(error_of(replaced(thermal_case, "    temperature: 300\n", "    temperature: -3\n")),
              HasSubstr("case.yaml:10:18: key 'bodies[0].temperature'"));
  EXPECT_THAT(error_of(replaced(thermal_case, "    temperature: 300\n",
                                "    temperature: 300\n    specific_heat: 900\n")),
              HasSubstr("key 'bodies[0].specific_heat': a deformable body takes its specific_heat "
                        "from its material"));
  EXPECT_THAT(
      error_of(replaced(thermal_case, "    specific_heat: 500\n", "    specific_heat: 0\n")),
      HasSubstr("case.yaml:16:20: key 'bodies[1].specific_heat'"));
  // Faces: a missing temperature, one given to an insulated face, a bad one, a z face in 2D.
  EXPECT_THAT(
      error_of(replaced(thermal_case, "{type: fixed_temperature, temperature: 310}",
                        "{type: fixed_temperature}")),
      HasSubstr(
          "case.yaml:21:10: key 'thermal.x_min': type: fixed_temperature needs a `temperature`"));
  EXPECT_THAT(
      error_of(replaced(thermal_case, "{type: insulated}", "{type: insulated, temperature: 300}")),
      HasSubstr("key 'thermal.y_max.temperature': an insulated face has no temperature"));
  EXPECT_THAT(error_of(replaced(thermal_case, "temperature: 290}", "temperature: -290}")),
              HasSubstr("case.yaml:22:"));
  EXPECT_THAT(error_of(replaced(thermal_case, "temperature: 290}", "temperature: -290}")),
              HasSubstr("key 'thermal.x_max.temperature'"));
  EXPECT_THAT(
      error_of(replaced(thermal_case, "y_max: {type: insulated}", "z_max: {type: insulated}")),
      HasSubstr("key 'thermal.z_max': a 2D case has no z faces"));
  EXPECT_THAT(error_of(replaced(thermal_case, "{type: insulated}", "{type: adiabatic}")),
              HasSubstr("key 'thermal.y_max.type'"));
  EXPECT_THAT(
      error_of(replaced(thermal_case, "  y_max: {type: insulated}", "  y_max: {temperature: 3}")),
      HasSubstr("thermal.y_max"));
  // enabled: true needs a thermal body.
  std::string mechanical =
      replaced(thermal_case, ", specific_heat: 835, thermal_conductivity: 0.4", "");
  mechanical = replaced(mechanical, "    specific_heat: 500\n    thermal_conductivity: 40\n", "");
  EXPECT_THAT(error_of(replaced(mechanical, "thermal:\n", "thermal:\n  enabled: true\n")),
              HasSubstr("case.yaml:19:12: key 'thermal.enabled': no body is thermal"));
}

TEST(MpmThermalCase, HelpListsTheThermalKeys) {
  const std::string help = mpm_case_help();
  for (const char* key :
       {"bodies[].temperature", "bodies[].specific_heat", "thermal.enabled", "thermal.x_min.type",
        "thermal.z_max.temperature", "  specific_heat", "  thermal_conductivity"})
    EXPECT_THAT(help, HasSubstr(key)) << key;
}

TEST(MpmThermalCase, ARunWritesTemperaturesAndTheThermalBalance) {
  const cosim::testing::ScratchDirectory dir;
  RunOptions options;
  options.config = dir.write("case.yaml", thermal_case);
  options.output = dir / "out";
  ASSERT_EQ(run_case(options), 0);
  EXPECT_THAT(read_text(dir / "out" / "particles.xdmf"), HasSubstr("Name=\"temperature\""));
  const std::string probes = read_text(dir / "out" / "probes.csv");
  EXPECT_THAT(probes, HasSubstr("mid_temperature [K]"));
  const auto summary = nlohmann::json::parse(read_text(dir / "out" / "summary.json"));
  const auto& conserved = summary["conserved"];
  std::printf("    summary.json conserved: %s\n", conserved.dump().c_str());
  const double start = conserved["thermal_energy_balance"]["start"];
  const double end = conserved["thermal_energy_balance"]["end"];
  const double energy = conserved["thermal_energy"]["start"];
  EXPECT_GT(energy, 0.0);
  EXPECT_NE(conserved["heat_through_faces"]["end"].get<double>(), 0.0);
  EXPECT_LT(std::abs(end - start), 1e-13 * energy);
  EXPECT_EQ(summary["case"]["heat_conduction"], true);
}

}  // namespace
}  // namespace mpm
