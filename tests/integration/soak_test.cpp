// A soak run: the demo job over 10^5 windows (about a minute), the resident
// memory of the coupler and of both participants sampled throughout (every
// 200 ms, some 300 windows apart). Once warm (a tenth of the run) none may
// grow by more than 1 % besides its one largest step between two samples: a
// leak of even a few bytes per window or message grows a little at every
// sample and would show, while a single step (an allocator's arena grown, a
// buffer's pages first touched: once, not per window) is not a leak. That
// step is held to 5 %.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "demo_job.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t soak_windows = 100000;
constexpr double window_s = 2.5e-3;  // the demo job's
constexpr double allowed_growth = 0.01;
constexpr double allowed_step = 0.05;

// VmRSS of /proc/<pid>/status [kB], 0 when the process is gone.
long resident_kib(pid_t pid) {
  std::ifstream in(fmt::format("/proc/{}/status", pid));
  std::string key;
  while (in >> key) {
    if (key == "VmRSS:") {
      long kib = 0;
      in >> kib;
      return kib;
    }
    std::string rest;
    std::getline(in, rest);
  }
  return 0;
}

// How far the coupler has got (its summary.json is rewritten as it goes).
double progress(const fs::path& summary) {
  try {
    const auto j = nlohmann::json::parse(read_text(summary));
    return j["windows"].get<double>() / static_cast<double>(soak_windows);
  } catch (const std::exception&) {
    return 0.0;
  }
}

TEST(Soak, MemoryStaysFlatOverManyWindows) {
  const fs::path dir = fresh_directory("soak");
  JobOptions o;
  o.end_time = static_cast<double>(soak_windows) * window_s;
  const fs::path job = write_job(dir, o);
  const pid_t cosim = spawn({binary("cosim").string(), "run", job.string(), "--output",
                             (dir / "run").string(), "--verbosity", "quiet"},
                            dir / "cosim.log");
  const std::map<std::string, pid_t> processes{
      {"cosim", cosim},
      {"left", wait_for_pid_file(dir / "run" / "left" / "pid", std::chrono::seconds(30))},
      {"right", wait_for_pid_file(dir / "run" / "right" / "pid", std::chrono::seconds(30))}};
  // Per process: the resident sizes sampled once warm.
  std::map<std::string, std::vector<long>> samples;
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::minutes(20)) {
    const double done = progress(dir / "run" / "summary.json");
    for (const auto& [name, pid] : processes) {
      const long kib = resident_kib(pid);
      if (kib == 0) continue;
      if (done >= 0.1) samples[name].push_back(kib);
    }
    if (resident_kib(cosim) == 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  const auto r = wait_for(cosim, dir / "cosim.log", std::chrono::seconds(600));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_csv(dir / "run" / "right" / "temperature_read.csv").size(), soak_windows);
  std::printf("soak: %zu windows in %.1f s (%.0f windows/s)\n", soak_windows, seconds,
              static_cast<double>(soak_windows) / seconds);
  for (const auto& [name, pid] : processes) {
    const std::vector<long>& kib = samples[name];
    ASSERT_GE(kib.size(), 10u) << name << " was hardly sampled warm";
    const long warm = kib.front();
    const long largest = *std::max_element(kib.begin(), kib.end());
    long step = 0;
    for (std::size_t i = 1; i < kib.size(); ++i) step = std::max(step, kib[i] - kib[i - 1]);
    const double growth = static_cast<double>(largest - warm - step) / static_cast<double>(warm);
    const double step_share = static_cast<double>(step) / static_cast<double>(warm);
    std::printf(
        "soak: %-6s resident %ld kB warm, %ld kB at most after (%zu samples): growth %+.3f %% "
        "besides its largest step of %.3f %% (limits %.0f %% and %.0f %%)\n",
        name.c_str(), warm, largest, kib.size(), 100.0 * growth, 100.0 * step_share,
        100.0 * allowed_growth, 100.0 * allowed_step);
    EXPECT_LE(growth, allowed_growth) << name;
    EXPECT_LE(step_share, allowed_step) << name;
  }
}

}  // namespace
}  // namespace cosim::testing
