// mpm-slope-seismic: a sand slope on a shaking table (Tran et al., MPMICE,
// "Validation of soil response to the seismic loading", after Hiraoka et
// al.; configs/mpm/validation/hiraoka_slope_seismic.yaml). The paper
// compares the toe displacement with the experiment in a figure only
// (Tran et al., Fig. 17), so the test checks the run through the solver's
// run driver, as users run it: exit 0, finite energies in summary.json, a
// probes.csv with the toe and crest time series; the toe moves outwards
// and the crest settles, both measured once the table has come back to
// rest at its starting position (the history is 10 whole cycles).
//
// CI runs 2.5 cm cells (0.4 x the case file's); COSIM_FULL_VALIDATION the
// case file's 1 cm.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/io/run_driver.hpp"
#include "text_files.hpp"

namespace mpm {
namespace {

namespace fs = std::filesystem;
using cosim::testing::read_text;

const fs::path case_dir = COSIM_SOURCE_DIR "/configs/mpm/validation";

#ifdef COSIM_FULL_VALIDATION
constexpr double resolution = 1.0;
#else
constexpr double resolution = 0.4;
#endif

constexpr double toe_threshold = 0.005;    // [m], 1 % of the slope height
constexpr double crest_threshold = 0.001;  // [m]

// The case file with its cells scaled by `scale`, written to `dir` (the
// velocity history then named by its absolute path).
fs::path write_scaled_case(const fs::path& dir, double scale) {
  std::string yaml = read_text(case_dir / "hiraoka_slope_seismic.yaml");
  const std::regex cells(R"(cells: \[(\d+), (\d+)\])");
  std::smatch m;
  if (!std::regex_search(yaml, m, cells))
    throw std::runtime_error("no `cells: [nx, ny]` in the case file");
  const auto scaled = [&](const std::string& n) { return std::lround(std::stod(n) * scale); };
  yaml = std::regex_replace(yaml, cells,
                            fmt::format("cells: [{}, {}]", scaled(m[1].str()), scaled(m[2].str())),
                            std::regex_constants::format_first_only);
  yaml =
      std::regex_replace(yaml, std::regex("velocity_history: shaking_table_velocity.csv"),
                         "velocity_history: " + (case_dir / "shaking_table_velocity.csv").string());
  fs::create_directories(dir);
  const fs::path file = dir / "hiraoka_slope_seismic.yaml";
  std::ofstream(file) << yaml;
  return file;
}

// probes.csv as columns by header name.
std::map<std::string, std::vector<double>> read_probes(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string value;
    for (std::size_t k = 0; k < names.size() && std::getline(row, value, ','); ++k)
      columns[names[k]].push_back(std::stod(value));
  }
  return columns;
}

TEST(MpmSlopeSeismicValidation, ToeMovesCrestSettlesNoInstability) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path dir = fs::path(COSIM_BINARY_DIR) / "validation_runs" / "mpm_slope_seismic";
  fs::remove_all(dir);
  RunOptions options;
  options.config = write_scaled_case(dir / "case", resolution);
  options.output = dir / "run";
  options.threads =
      1;  // OpenMP teams spin-wait: on a shared, loaded CI machine one thread is faster
  options.verbosity = cosim::Verbosity::quiet;
  const int exit_code = run_case(options);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(exit_code, 0) << read_text(options.output / "log.txt");

  const auto summary = nlohmann::json::parse(read_text(options.output / "summary.json"));
  for (const char* energy : {"kinetic_energy", "strain_energy", "gravitational_energy"}) {
    const auto& end = summary["conserved"][energy]["end"];
    ASSERT_TRUE(end.is_number()) << energy << " at the end: " << end.dump();
    EXPECT_TRUE(std::isfinite(end.get<double>())) << energy;
  }

  ASSERT_TRUE(fs::exists(options.output / "probes.csv"));
  const auto probes = read_probes(options.output / "probes.csv");
  ASSERT_TRUE(probes.contains("toe_displacement_x [m]") &&
              probes.contains("crest_displacement_y [m]"));
  const auto& time = probes.at("time [s]");
  const auto& toe = probes.at("toe_displacement_x [m]");
  const auto& crest = probes.at("crest_displacement_y [m]");
  ASSERT_GT(time.size(), 100u);
  for (std::size_t k = 0; k < time.size(); ++k)
    ASSERT_TRUE(std::isfinite(toe[k]) && std::isfinite(crest[k])) << "at t = " << time[k];
  const double toe_final = toe.back();
  const double settlement = -crest.back();
  fmt::print(
      "mpm-slope-seismic ({:.1f} cm cells): {} probe rows to t = {:.2f} s; toe displacement {:.1f} "
      "mm "
      "(must exceed {:.1f} mm, outwards), crest settlement {:.1f} mm (must exceed {:.1f} mm); wall "
      "{:.1f} s\n",
      1.0 / resolution, time.size(), time.back(), 1e3 * toe_final, 1e3 * toe_threshold,
      1e3 * settlement, 1e3 * crest_threshold, wall);
  fmt::print("  toe displacement x [mm] every 0.1 s:");
  for (std::size_t k = 0; k < time.size(); k += 10) fmt::print(" {:.1f}", 1e3 * toe[k]);
  fmt::print("\n");
  EXPECT_GT(toe_final, toe_threshold);
  EXPECT_GT(settlement, crest_threshold);
}

}  // namespace
}  // namespace mpm
