// The explicit coupling's stability bound (architecture.md §3) on the soil column
// in ICE water of configs/ice_coupled/job.yaml: 0.125 m cells, water at
// 2.15 GPa, the undrained wave at about 2 km/s, a bound of about 60 us. The
// shipped 50 us window runs without a word; a 10 ms window (the pore
// pressures of such a run reach -2 and +3 MPa against 0.11 MPa hydrostatic)
// is refused before its first window, naming the key and its line, unless
// the job accepts it, which it then runs with the warning in its log and
// summary.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

// The shipped job with another window, end time and stability_check block,
// its participants' configs taken from configs/ice_coupled.
fs::path ice_job(const fs::path& dir, double window, double end_time,
                 const std::string& stability_check) {
  const fs::path shipped = fs::path(COSIM_SOURCE_DIR) / "configs" / "ice_coupled";
  std::string job = read_text(shipped / "job.yaml");
  auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = job.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    job.replace(at, from.size(), to);
  };
  replace("end_time: 0.1\n", fmt::format("end_time: {}\n", end_time));
  replace("window: 5.0e-5\n", fmt::format("window: {}\n{}", window, stability_check));
  replace("config: water.yaml", "config: " + (shipped / "water.yaml").string());
  replace("config: soil_column.yaml", "config: " + (shipped / "soil_column.yaml").string());
  write_text(dir / "job.yaml", job);
  return dir / "job.yaml";
}

ProcessResult run_job(const fs::path& job, const fs::path& output) {
  return run({binary("cosim").string(), "run", job.string(), "--output", output.string()},
             std::chrono::seconds(300));
}

nlohmann::json stability_of(const fs::path& run) {
  return nlohmann::json::parse(read_text(run / "summary.json"))["stability"];
}

TEST(ExplicitStability, AWindowWithinTheBoundRunsQuietly) {
  const fs::path dir = fresh_directory("stability_within");
  const auto r = run_job(ice_job(dir, 5e-5, 2e-3, ""), dir / "run");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto stability = stability_of(dir / "run");
  const double bound = stability["bound_s"];
  std::printf("explicit window bound %.3g s (wave %.4g m/s), window 5e-5 s\n", bound,
              stability["wave_speed_m_per_s"].get<double>());
  EXPECT_GT(bound, 5e-5);
  EXPECT_LT(bound, 1e-4);
  EXPECT_THAT(read_text(dir / "run" / "log.txt"),
              Not(HasSubstr("times the explicit coupling's stability bound")));
}

TEST(ExplicitStability, AWindowFarAboveTheBoundIsRefusedBeforeItsFirstWindow) {
  const fs::path dir = fresh_directory("stability_refused");
  const auto r = run_job(ice_job(dir, 1e-2, 0.1, ""), dir / "run");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("job.yaml:18:"));
  EXPECT_THAT(r.output, HasSubstr("key 'window'"));
  EXPECT_THAT(r.output, HasSubstr("times the explicit coupling's stability bound"));
  EXPECT_THAT(r.output, HasSubstr("accept_unstable"));
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_EQ(summary["windows"], 0);
  EXPECT_EQ(summary["status"]["exit_code"], 2);
}

TEST(ExplicitStability, AnAcceptedUnstableWindowRunsWithTheWarning) {
  const fs::path dir = fresh_directory("stability_accepted");
  const auto r =
      run_job(ice_job(dir, 1e-3, 2e-3, "stability_check: {accept_unstable: true}\n"), dir / "run");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(read_text(dir / "run" / "log.txt"),
              HasSubstr("times the explicit coupling's stability bound"));
  EXPECT_GT(stability_of(dir / "run")["window_over_bound"].get<double>(), 10.0);
}

}  // namespace
}  // namespace cosim::testing
