// End to end: `ice_fluid --cosim-repeat-windows` runs every coupling window
// twice, going back to the state saved at its start once, as implicit
// coupling does. A correct save and restore writes exactly what a plain run
// writes: every snapshot's datasets and attributes bit for bit (HDF5 files
// are compared by contents: their object headers hold when each object was
// made), the XDMF index, gauges.csv and steps.csv byte for byte. Also prints
// what the saves and restores cost against the solver's time.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "hdf5_contents.hpp"
#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

// The shipped Martin & Moyce dam break, coarse and short, in 13 windows (12
// of 4 ms and one of 2 ms): snapshots fall inside windows (0.01 s) and on
// their ends (0.02 s), a gauge records every step.
constexpr int windows = 13;

std::string martin_moyce_in_windows() {
  std::string text =
      read_text(fs::path(COSIM_SOURCE_DIR) / "configs" / "ice" / "martin_moyce.yaml");
  text = replaced(text, "cells: [100, 50]", "cells: [80, 40]");
  text = replaced(text, "end_time: 0.19   # t sqrt(2g/a) = 3.5", "end_time: 0.05\nwindow: 0.004");
  text = replaced(text, "  every: 0.01",
                  "  every: 0.01\n  gauges: [{name: toe, point: [0.07, 0.005]}]");
  return text;
}

std::set<std::string> file_names(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
  return names;
}

TEST(IceFluidRepeat, RepeatedWindowsWriteWhatAPlainRunWrites) {
  const fs::path dir = fresh_directory("ice_fluid_repeat");
  write_text(dir / "case.yaml", martin_moyce_in_windows());
  for (const char* name : {"plain", "repeated"}) {
    std::vector<std::string> args{binary("ice_fluid").string(),
                                  "--config",
                                  (dir / "case.yaml").string(),
                                  "--output",
                                  (dir / name).string(),
                                  "--verbosity",
                                  "quiet"};
    if (std::string(name) == "repeated") args.push_back("--cosim-repeat-windows");
    const ProcessResult r = run(args, std::chrono::seconds(300));
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.output;
  }
  const fs::path plain = dir / "plain", repeated = dir / "repeated";

  std::set<std::string> files = file_names(plain);
  EXPECT_EQ(files, file_names(repeated));
  for (const char* record : {"summary.json", "log.txt"}) files.erase(record);
  EXPECT_EQ(files.count("ice_000005.h5"), 1u) << "snapshots at 0, 0.01, ..., 0.05 s";
  for (const std::string& file : files) {
    if (fs::path(file).extension() == ".h5")
      EXPECT_EQ(hdf5_contents(plain / file), hdf5_contents(repeated / file)) << file;
    else
      EXPECT_EQ(read_text(plain / file), read_text(repeated / file)) << file;
  }
  EXPECT_GT(read_csv(plain / "gauges.csv").size(), 2u * windows) << "a row per step";

  const auto a = nlohmann::json::parse(read_text(plain / "summary.json"));
  const auto b = nlohmann::json::parse(read_text(repeated / "summary.json"));
  EXPECT_EQ(a["steps"], b["steps"]);
  EXPECT_EQ(a["conserved"], b["conserved"]);
  for (const char* metric : {"min_time_step", "mean_cg_iterations", "max_cg_iterations",
                             "rejected_steps", "max_volume_closure"})
    EXPECT_EQ(a["metrics"][metric], b["metrics"][metric]) << metric;
  EXPECT_FALSE(a["metrics"].contains("save_restore_seconds")) << "a plain run saves nothing";
  ASSERT_TRUE(b["metrics"].contains("save_restore_seconds"));
  const double save_restore = b["metrics"]["save_restore_seconds"]["value"].get<double>();
  const double advance = b["wall_time_s"]["phases"]["advance"].get<double>();
  const double share = b["metrics"]["save_restore_share"]["value"].get<double>();
  fmt::print(
      "{} cells, {} windows of {:.1f} steps on average: save + restore {:.3f} ms per window, the "
      "solver {:.1f} ms per window attempt: {:.2e} of it\n",
      b["case"]["cells"].get<int>(), windows, b["steps"].get<double>() / windows,
      1e3 * save_restore / windows, 1e3 * advance / (2 * windows), share);
  EXPECT_GT(share, 0.0);
}

}  // namespace
}  // namespace cosim::testing
