// openfoam_adapter's cost per window: the adapter's writes, the solver's
// start-up (launch to its first time step), its stepping and the fields read
// back, for a generated water tank of 800, 3 200 and 20 000 cells, serial
// and on two processes (decomposed along x, mpirun), 10 steps of 1 ms per
// window; then the same steps in one start (the
// continuous reference), the restart overhead's share of a window, and the
// steps per window at which that share falls below 25 %. Medians over the
// windows after the first (its start builds the mesh caches the others
// also rebuild, but it also reads the setFields output). Prints figures;
// never pass/fail.
//
//   build/bin/openfoam_window_bench [windows = 10]
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_process.hpp"
#include "text_files.hpp"

namespace {

namespace fs = std::filesystem;

std::string tank_case(int nx, int ny, double window, double end_time, int processes) {
  std::string text = fmt::format(R"(kind: openfoam_case
name: tank_{}x{}
generate:
  dimension: 2
  grid: {{origin: [0.0, 0.0], upper: [1.0, 0.5], cells: [{}, {}]}}
  gravity: [0.0, -9.81]
  fluids:
    water: {{density: 1000, viscosity: 1.0e-3}}
    air: {{density: 1, viscosity: 1.8e-5}}
  water:
    - box: {{lower: [0.0, 0.0], upper: [0.4, 0.35]}}
  boundaries: {{y_max: atmosphere}}
end_time: {}
time_step: 1.0e-3
window: {}
output: {{every: {}}}
)",
                                 nx, ny, nx, ny, end_time, window, end_time);
  if (processes > 1) text += fmt::format("parallel: {{processes: {}}}\n", processes);
  return text;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

nlohmann::json run(const std::string& name, const std::string& text) {
  const fs::path dir = cosim::testing::fresh_directory("openfoam_window_bench_" + name);
  cosim::testing::write_text(dir / "case.yaml", text);
  const auto r = cosim::testing::run(
      {cosim::testing::binary("openfoam_adapter").string(), "--config",
       (dir / "case.yaml").string(), "--output", (dir / "out").string(), "--verbosity", "quiet"},
      std::chrono::seconds(3600));
  if (r.exit_code != 0) {
    fmt::print("{}: openfoam_adapter exited {}:\n{}\n", name, r.exit_code, r.output);
    std::exit(1);
  }
  return nlohmann::json::parse(cosim::testing::read_text(dir / "out" / "summary.json"));
}

std::vector<double> after_first(const nlohmann::json& values) {
  std::vector<double> v;
  for (std::size_t i = 1; i < values.size(); ++i) v.push_back(values[i].get<double>());
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  const int windows = argc > 1 ? std::max(2, std::atoi(argv[1])) : 10;
  const int steps_per_window = 10;
  const double window = steps_per_window * 1e-3;
  fmt::print(
      "openfoam_adapter window cost: interFoam, 2D tank, {} windows of {} steps (1 ms), "
      "serial and np = 2; medians of windows 2..{} [s]\n",
      windows, steps_per_window, windows);
  fmt::print("{:>7} {:>3} {:>8} {:>8} {:>9} {:>8} {:>9} {:>11} {:>9} {:>10}\n", "cells", "np",
             "write", "startup", "stepping", "read", "window", "continuous", "overhead",
             "k for 25%");
  for (const int np : {1, 2}) {
    for (const auto& [nx, ny] : {std::pair{40, 20}, std::pair{80, 40}, std::pair{200, 100}}) {
      const double end = windows * window;
      const std::string name = fmt::format("{}x{}_np{}", nx, ny, np);
      const auto restarted = run(name, tank_case(nx, ny, window, end, np));
      const auto& w = restarted["openfoam_windows"];
      const double write = median(after_first(w["adapter_write_s"]));
      const double startup = median(after_first(w["solver_startup_s"]));
      const double stepping = median(after_first(w["solver_stepping_s"]));
      const double read = median(after_first(w["field_read_s"]));
      const double per_window = write + startup + stepping + read;
      // The same steps in one start: its stepping per window is what a
      // window costs without restarts.
      const auto continuous = run(name + "_continuous", tank_case(nx, ny, end, end, np));
      const double continuous_window =
          continuous["openfoam_windows"]["solver_stepping_s"][0].get<double>() / windows;
      const double overhead = per_window - continuous_window;
      const double per_step = continuous_window / steps_per_window;
      // overhead / (overhead + k per_step) < 0.25  <=>  k > 3 overhead / per_step
      const double k25 = std::ceil(3.0 * overhead / per_step);
      fmt::print(
          "{:>7} {:>3} {:>8.4f} {:>8.3f} {:>9.3f} {:>8.4f} {:>9.3f} {:>11.3f} {:>8.0f}% "
          "{:>10.0f}\n",
          nx * ny, np, write, startup, stepping, read, per_window, continuous_window,
          100.0 * overhead / per_window, k25);
    }
  }
  return 0;
}
