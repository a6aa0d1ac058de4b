// Wall time of the clay-column pairing (Zheng et al., Sec. 4.3, R_ws = 1.0)
// split into MPM compute, SWE compute and coupling, as medians of a few runs
// of `cosim run` (part of the `bench` target; never a test).
//
//   swe_pairing_bench [--runs N] [--job configs/clay_still_water_Rws1.0.yaml]
//
// From the participants' summary.json: MPM compute = its total minus its
// coupling transport and waiting; SWE compute = its advance, bed update,
// traction and output phases; coupling = the job's wall time minus the
// slower side's compute (transport, mapping and the wait for the partner).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_process.hpp"
#include "text_files.hpp"

namespace fs = std::filesystem;
namespace ct = cosim::testing;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double phase(const nlohmann::json& summary, const char* name) {
  const auto& phases = summary["wall_time_s"]["phases"];
  return phases.contains(name) ? phases[name].get<double>() : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  fs::path job = fs::path(COSIM_SOURCE_DIR) / "configs" / "clay_still_water_Rws1.0.yaml";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--runs") runs = std::stoi(argv[i + 1]);
    if (key == "--job") job = argv[i + 1];
  }
  std::vector<double> total, mpm, swe, coupling, windows;
  for (int r = 0; r < runs; ++r) {
    const fs::path out = ct::fresh_directory(fmt::format("swe_pairing_bench_{}", r));
    const auto result = ct::run({ct::binary("cosim").string(), "run", job.string(), "--output",
                                 out.string(), "--verbosity", "quiet"},
                                std::chrono::seconds(1800));
    if (result.exit_code != 0) {
      fmt::print(stderr, "cosim run failed ({}):\n{}\n", result.exit_code, result.output);
      return 1;
    }
    const auto job_summary = nlohmann::json::parse(ct::read_text(out / "summary.json"));
    const auto soil = nlohmann::json::parse(ct::read_text(out / "soil" / "summary.json"));
    const auto water = nlohmann::json::parse(ct::read_text(out / "water" / "summary.json"));
    const double wall = job_summary["wall_time_s"]["total"].get<double>();
    const double soil_compute = soil["wall_time_s"]["total"].get<double>() -
                                soil["coupling"]["transport_s"].get<double>() -
                                soil["coupling"]["waiting_s"].get<double>();
    const double water_compute = phase(water, "advance") + phase(water, "bed_update") +
                                 phase(water, "traction") + phase(water, "output") +
                                 phase(water, "setup") + phase(water, "read_case");
    total.push_back(wall);
    mpm.push_back(soil_compute);
    swe.push_back(water_compute);
    coupling.push_back(wall - std::max(soil_compute, water_compute));
    windows.push_back(job_summary["windows"].get<double>());
  }
  fmt::print("clay column pairing ({}), median of {} runs:\n", job.filename().string(), runs);
  fmt::print("  wall time         {:8.2f} s  ({} windows)\n", median(total), median(windows));
  fmt::print("  MPM compute       {:8.2f} s  ({:4.1f} %)\n", median(mpm),
             100.0 * median(mpm) / median(total));
  fmt::print("  SWE compute       {:8.2f} s  ({:4.1f} %)\n", median(swe),
             100.0 * median(swe) / median(total));
  fmt::print("  coupling          {:8.2f} s  ({:4.1f} %), {:.0f} us per window\n", median(coupling),
             100.0 * median(coupling) / median(total), 1e6 * median(coupling) / median(windows));
  return 0;
}
