#include "cosim/io/run_summary.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <thread>

#include "cosim/error.hpp"
#include "scratch_directory.hpp"

namespace cosim {
namespace {

using testing::ScratchDirectory;

// "YYYY-MM-DDThh:mm:ss.mmmZ"
bool is_iso8601_utc(const std::string& text) {
  const std::string shape = "dddd-dd-ddTdd:dd:dd.dddZ";
  if (text.size() != shape.size()) return false;
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const bool digit = std::isdigit(static_cast<unsigned char>(text[i])) != 0;
    if (shape[i] == 'd' ? !digit : text[i] != shape[i]) return false;
  }
  return true;
}

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(PhaseTimer, ScopesAccumulatePerPhase) {
  PhaseTimer timer;
  for (int i = 0; i < 3; ++i) {
    const auto scope = timer.measure("advance");
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  timer.add("mapping", 0.25);
  timer.add("mapping", 0.5);
  std::cout << "advance measured " << timer.seconds("advance") << " s for 3 x 5 ms\n";
  EXPECT_GE(timer.seconds("advance"), 0.015);
  EXPECT_LT(timer.seconds("advance"), 1.0);
  EXPECT_EQ(timer.seconds("mapping"), 0.75);
  EXPECT_EQ(timer.seconds("never"), 0.0);
  EXPECT_DOUBLE_EQ(timer.total_seconds(), timer.seconds("advance") + 0.75);
  EXPECT_EQ(timer.phases().size(), 2u);
}

TEST(RunSummary, ValidAfterEveryWriteAndRoundTripsThroughJson) {
  ScratchDirectory dir;
  RunSummary summary(dir.path(), "mpm_solver");
  summary.set_config("configs/clay.yaml", 0x0123456789abcdefULL);
  summary.set_conserved_start("mass", 2.0, "kg");
  summary.set_section("participants", {{"soil", "mpm_solver"}});
  for (int window = 1; window <= 3; ++window) {
    summary.set_windows(window);
    summary.set_steps(10 * window);
    summary.phases().add("advance", 0.1);
    summary.write();
    const auto j = read_json(summary.path());
    EXPECT_EQ(j["windows"], window);
    EXPECT_EQ(j["steps"], 10 * window);
    EXPECT_EQ(j["status"]["state"], "running");
    EXPECT_TRUE(j["finished_at"].is_null());
    EXPECT_DOUBLE_EQ(j["wall_time_s"]["phases"]["advance"].get<double>(), 0.1 * window);
    EXPECT_FALSE(std::filesystem::exists(dir / ".summary.json.tmp"));
  }
  summary.set_conserved_end("mass", 2.0 * (1.0 + 1e-13), "kg");
  summary.set_metric("runout_distance", 3.25, "m");
  summary.finish(ExitCode::success, "reached end_time");

  const auto j = read_json(summary.path());
  EXPECT_EQ(j["program"], "mpm_solver");
  EXPECT_EQ(j["version"], COSIM_VERSION);
  EXPECT_EQ(j["config"]["path"], "configs/clay.yaml");
  EXPECT_EQ(j["config"]["hash"], "0123456789abcdef");
  EXPECT_EQ(j["status"]["state"], "finished");
  EXPECT_EQ(j["status"]["exit_code"], 0);
  EXPECT_EQ(j["status"]["exit_status"], "success");
  EXPECT_EQ(j["status"]["message"], "reached end_time");
  EXPECT_EQ(j["conserved"]["mass"]["unit"], "kg");
  EXPECT_EQ(j["conserved"]["mass"]["start"], 2.0);
  const double change = j["conserved"]["mass"]["relative_change"];
  std::cout << "mass relative change recorded: " << change << "\n";
  EXPECT_NEAR(change, 1e-13, 1e-16);
  EXPECT_EQ(j["metrics"]["runout_distance"]["value"], 3.25);
  EXPECT_EQ(j["metrics"]["runout_distance"]["unit"], "m");
  EXPECT_EQ(j["participants"]["soil"], "mpm_solver");
  EXPECT_TRUE(is_iso8601_utc(j["started_at"])) << j["started_at"];
  EXPECT_TRUE(is_iso8601_utc(j["finished_at"])) << j["finished_at"];
  EXPECT_FALSE(is_iso8601_utc("2024-05-01 12:34:56.789Z"));
  EXPECT_LE(j["started_at"].get<std::string>(), j["finished_at"].get<std::string>());
  EXPECT_GE(j["wall_time_s"]["total"].get<double>(), 0.0);

  summary.write();  // after finish: total wall time stays frozen
  EXPECT_EQ(read_json(summary.path())["wall_time_s"]["total"], j["wall_time_s"]["total"]);
}

TEST(RunSummary, FailureStatusAndReservedSections) {
  ScratchDirectory dir;
  RunSummary summary(dir / "nested" / "run", "cosim");
  EXPECT_THROW(summary.set_section("metrics", 1), InputError);
  summary.set_metric("nan_metric", std::nan(""), "1");
  summary.finish(ExitCode::participant_failed, "participant 'water' exited with status 4");
  const auto j = read_json(summary.path());
  EXPECT_EQ(j["status"]["exit_code"], 3);
  EXPECT_EQ(j["status"]["exit_status"], "participant_failed");
  EXPECT_TRUE(j["metrics"]["nan_metric"]["value"].is_null());
  EXPECT_TRUE(j["config"]["hash"].is_null());
}

TEST(Iso8601, FormatsTheEpochAndMilliseconds) {
  const auto t = std::chrono::system_clock::time_point(std::chrono::milliseconds(1234));
  EXPECT_EQ(iso8601_utc(t), "1970-01-01T00:00:01.234Z");
  const auto y2k = std::chrono::sys_days(std::chrono::year(2000) / 2 / 29) + std::chrono::hours(23);
  EXPECT_EQ(iso8601_utc(y2k), "2000-02-29T23:00:00.000Z");
}

}  // namespace
}  // namespace cosim
