// The depth-averaged mass (mpm_solver, depth_averaged_case) coupled by
// `cosim run` to the two-phase shallow water (swe_fluid): the shipped job
// configs/depth_averaged_coupled/job.yaml, a saturated cohesive block that
// slides into a lake and breaks up. Asserted: what crosses between the two
// processes is conserved to round-off (the fluid the blocks release, the
// drag's impulse, the water's volume, the mass's mass), and the lake holds
// the mass back against the same mass sliding dry.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "run_process.hpp"
#include "text_files.hpp"

namespace fs = std::filesystem;
namespace ct = cosim::testing;

namespace {

const fs::path configs = fs::path(COSIM_SOURCE_DIR) / "configs" / "depth_averaged_coupled";

nlohmann::json summary(const fs::path& run) {
  return nlohmann::json::parse(ct::read_text(run / "summary.json"));
}

double metric(const nlohmann::json& s, const char* name) {
  return s["metrics"][name]["value"].get<double>();
}

TEST(DepthAveragedPairing, ConservesWhatCrossesAndTheLakeHoldsTheMassBack) {
  const fs::path out = ct::fresh_directory("depth_averaged_pairing");
  const auto coupled =
      ct::run({ct::binary("cosim").string(), "run", (configs / "job.yaml").string(), "--output",
               out.string(), "--verbosity", "quiet"},
              std::chrono::seconds(600));
  ASSERT_EQ(coupled.exit_code, 0) << coupled.output;
  const fs::path dry_out = ct::fresh_directory("depth_averaged_pairing_dry");
  const auto dry = ct::run({ct::binary("mpm_solver").string(), "--config",
                            (configs / "slide.yaml").string(), "--output", dry_out.string()},
                           std::chrono::seconds(600));
  ASSERT_EQ(dry.exit_code, 0) << dry.output;

  const double mapping_error = metric(summary(out), "max_conservative_mapping_error");
  fmt::print("largest conservative mapping error {:.2e} (tolerance 1e-12)\n", mapping_error);
  EXPECT_LE(mapping_error, 1e-12);
  const auto mass = summary(out / "mass");
  const auto lake = summary(out / "lake");
  const double rho_f = 1000.0;

  // The blocks broke up and their water went into the lake: what the mass
  // lost is what it released, and the lake took all of it but the last
  // window's (in flight when the job ended).
  const double released = metric(mass, "fluid_released");
  const double in_flight = metric(mass, "fluid_released_last_window");
  const double added = metric(lake, "two_phase_volume_added");
  const double mass_start = mass["conserved"]["mass"]["start"].get<double>();
  const double mass_end = mass["conserved"]["mass"]["end"].get<double>();
  fmt::print("fluid released {:.6g} m^3 ({:.3g} in the last window), taken by the lake {:.6g}\n",
             released, in_flight, added);
  EXPECT_GT(released, 1e-3);
  EXPECT_NEAR(added, released - in_flight, 1e-12 * released);
  const double mass_error = (mass_start - mass_end - rho_f * released) / mass_start;
  fmt::print("mass lost - rho_f x released: {:.2e} of the mass (tolerance 1e-12)\n", mass_error);
  EXPECT_LT(std::abs(mass_error), 1e-12);

  // The lake's water is its start plus what it took, to round-off.
  const double volume_start = lake["conserved"]["water_volume"]["start"].get<double>();
  const double volume_end = lake["conserved"]["water_volume"]["end"].get<double>();
  const double volume_error = (volume_end - volume_start - added) / volume_start;
  fmt::print("water volume end - start - taken: {:.2e} of the volume (tolerance 1e-12)\n",
             volume_error);
  EXPECT_LT(std::abs(volume_error), 1e-12);

  // The drag's impulse: what the water gave the solids is what the points received.
  const double scale = mass_start * std::sqrt(9.81 * 1.5);
  for (const char* axis : {"x", "y"}) {
    const double sent = metric(lake, fmt::format("drag_impulse_sent_{}", axis).c_str());
    const double received = metric(mass, fmt::format("drag_impulse_received_{}", axis).c_str());
    fmt::print("drag impulse {}: sent {:.9g} kg m/s, received {:.9g} kg m/s\n", axis, sent,
               received);
    EXPECT_NEAR(received, sent, 1e-12 * scale);
  }
  EXPECT_LT(std::abs(metric(lake, "drag_impulse_sent_x")), scale);
  EXPECT_EQ(metric(mass, "drag_impulse_unplaced"), 0.0);

  // The lake holds the mass back: its centre stops short of the dry mass's
  // (a few thin fragments ride the wave much further: the front is not the
  // measure).
  const double centre = metric(mass, "centre_of_mass_x");
  const double dry_centre = metric(summary(dry_out), "centre_of_mass_x");
  fmt::print("centre of mass after 8 s: x = {:.3f} m in the lake, {:.3f} m dry\n", centre,
             dry_centre);
  EXPECT_GT(centre, 15.0);  // it reached the lake's floor (the slope ends at x = 15 m)
  EXPECT_LT(centre, dry_centre - 0.5);
}

// A copy of the shipped job in a fresh directory, `from` replaced by `to` in
// one of its files.
fs::path edited_job(const std::string& name, const std::string& file, const std::string& from,
                    const std::string& to) {
  const fs::path dir = ct::fresh_directory(name);
  for (const auto& entry : fs::directory_iterator(configs))
    fs::copy_file(entry.path(), dir / entry.path().filename());
  std::string text = ct::read_text(dir / file);
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no '" + from + "' in " + file);
  text.replace(at, from.size(), to);
  ct::write_text(dir / file, text);
  return dir;
}

TEST(DepthAveragedPairing, RefusesAnInclinedTerrainNamingTheKeyAndLine) {
  const fs::path dir = edited_job("depth_averaged_pairing_inclined", "slide.yaml", "terrain:\n",
                                  "terrain:\n  inclination: 10\n");
  const fs::path out = ct::fresh_directory("depth_averaged_pairing_inclined_run");
  const auto r = ct::run({ct::binary("cosim").string(), "run", (dir / "job.yaml").string(),
                          "--output", out.string(), "--verbosity", "quiet"},
                         std::chrono::seconds(120));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  const std::string console = ct::read_text(out / "mass" / "console.log");
  EXPECT_NE(console.find("slide.yaml:"), std::string::npos) << console;
  EXPECT_NE(console.find("key 'terrain.inclination'"), std::string::npos) << console;
}

TEST(DepthAveragedPairing, TheWaterRefusesASolidLayerWithoutItsTwoPhaseMode) {
  const fs::path dir = edited_job("depth_averaged_pairing_single_phase", "lake.yaml",
                                  "two_phase:", "single_phase_now:");
  // the block under it is no longer a key of the case either: drop it
  std::string text = ct::read_text(dir / "lake.yaml");
  const auto start = text.find("single_phase_now:");
  const auto end = text.find("output:");
  text.erase(start, end - start);
  ct::write_text(dir / "lake.yaml", text);
  const auto r = ct::run(
      {ct::binary("swe_fluid").string(), "--validate", "--config", (dir / "lake.yaml").string()},
      std::chrono::seconds(60));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("coupling.reads"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("two_phase"), std::string::npos) << r.output;
}

}  // namespace
