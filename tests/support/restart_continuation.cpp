#include "restart_continuation.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <thread>

#include "hdf5_contents.hpp"
#include "text_files.hpp"

namespace cosim::testing {

namespace fs = std::filesystem;

ProcessResult run_job(const fs::path& job, const fs::path& output,
                      const std::vector<std::string>& extra) {
  std::vector<std::string> args{binary("cosim").string(), "run", job.string(), "--output",
                                output.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return run(args, std::chrono::seconds(600));
}

namespace {

std::vector<std::string> lines_of(const fs::path& file) {
  std::istringstream in(read_text(file));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The rows of a CSV after the checkpoint: those whose first column, the
// window or the time, is past the checkpoint's.
std::vector<std::string> rows_after(const fs::path& file, std::size_t window, double time) {
  std::vector<std::string> rows;
  const auto lines = lines_of(file);
  if (lines.empty()) return rows;
  const bool by_window = lines[0].rfind("window", 0) == 0;
  const double after = by_window ? static_cast<double>(window) : time * (1.0 + 1e-12);
  for (std::size_t i = 1; i < lines.size(); ++i)
    if (std::stod(lines[i].substr(0, lines[i].find(','))) > after) rows.push_back(lines[i]);
  return rows;
}

}  // namespace

// Every CSV the uninterrupted run wrote, in the run directory and its
// participants' directories, against the continued run's: the same header,
// and the rows after the checkpoint's window the same text. Returns how
// many rows were compared.
std::size_t expect_same_continuation(const fs::path& whole, const fs::path& continued,
                                     std::size_t window, double time) {
  std::size_t compared = 0, files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(whole)) {
    if (entry.path().extension() != ".csv") continue;
    const fs::path relative = fs::relative(entry.path(), whole);
    if (relative.string().find("checkpoints") == 0) continue;
    const fs::path other = continued / relative;
    ++files;
    if (!fs::exists(other)) {
      ADD_FAILURE() << "the continued run has no " << relative;
      continue;
    }
    EXPECT_EQ(lines_of(entry.path()).front(), lines_of(other).front()) << relative;
    const auto expected = rows_after(entry.path(), window, time);
    const auto got = rows_after(other, window, time);
    EXPECT_EQ(got, expected) << relative;
    EXPECT_EQ(lines_of(other).size(), expected.size() + 1)
        << relative << ": the continued run wrote rows of windows before the checkpoint";
    compared += expected.size();
  }
  EXPECT_GT(files, 0u);
  return compared;
}

namespace {

// The last snapshot file (`<base>_<step>.h5`) of every snapshot series under
// a run directory, by its directory and base name.
std::map<std::string, fs::path> last_snapshots(const fs::path& run) {
  static const std::regex numbered(R"((.*)_(\d{6})\.h5)");
  std::map<std::string, fs::path> last;
  for (const auto& entry : fs::recursive_directory_iterator(run)) {
    const fs::path relative = fs::relative(entry.path(), run);
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (relative.string().find("checkpoints") == 0 || !std::regex_match(name, m, numbered))
      continue;
    const std::string key = (relative.parent_path() / m[1].str()).string();
    if (!last.count(key) || last[key].filename() < entry.path().filename())
      last[key] = entry.path();
  }
  return last;
}

}  // namespace

// The last snapshot of every series the continued run wrote holds what the
// uninterrupted run's does, every dataset and attribute bit for bit but the
// snapshot's index in its series (a restarted series counts from 0).
std::size_t expect_same_last_snapshots(const fs::path& whole, const fs::path& continued) {
  const auto expected = last_snapshots(whole);
  std::size_t compared = 0;
  for (const auto& [series, file] : last_snapshots(continued)) {
    if (!expected.count(series)) {
      ADD_FAILURE() << "the uninterrupted run has no snapshots " << series;
      continue;
    }
    auto got = hdf5_contents(file);
    auto want = hdf5_contents(expected.at(series));
    got.erase("@step");
    want.erase("@step");
    std::vector<std::string> differing;
    for (const auto& [object, bytes] : want)
      if (!got.count(object) || got.at(object) != bytes) differing.push_back(object);
    EXPECT_TRUE(differing.empty() && got.size() == want.size())
        << series << ": " << differing.size() << " objects differ, e.g. "
        << (differing.empty() ? std::string("(extra objects)") : differing.front());
    ++compared;
  }
  return compared;
}

fs::path checkpoint_of(const fs::path& run, std::size_t window) {
  return run / "checkpoints" / fmt::format("window_{:09d}", window);
}

std::vector<std::string> checkpoints_in(const fs::path& run) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(run / "checkpoints"))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Runs the job whole with checkpoints every `every` windows, then again from
// the checkpoint of `window`; compares what both wrote after it.
void expect_restart_continues(const fs::path& dir, const fs::path& job, const std::string& every,
                              std::size_t window) {
  const auto whole =
      run_job(job, dir / "whole", {"--checkpoint-every", every, "--checkpoints-kept", "100"});
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const auto continued =
      run_job(job, dir / "continued", {"--restart", checkpoint_of(dir / "whole", window).string()});
  ASSERT_EQ(continued.exit_code, 0) << continued.output;
  const double time = nlohmann::json::parse(read_text(checkpoint_of(dir / "whole", window) /
                                                      "manifest.json"))["time_s"]
                          .get<double>();
  const std::size_t rows = expect_same_continuation(dir / "whole", dir / "continued", window, time);
  const std::size_t snapshots = expect_same_last_snapshots(dir / "whole", dir / "continued");
  std::printf(
      "%s: restarted after window %zu; %zu rows after it and the last snapshot of %zu series "
      "equal the uninterrupted run's\n",
      job.parent_path().filename().c_str(), window, rows, snapshots);
  EXPECT_GT(rows, 0u);
  const auto summary = nlohmann::json::parse(read_text(dir / "continued" / "summary.json"));
  EXPECT_EQ(summary["restart"]["window"].get<std::size_t>(), window);
  EXPECT_EQ(summary["status"]["exit_code"].get<int>(), 0);
}

StoppedRun stop_with_sigterm(const fs::path& dir, const fs::path& job) {
  const pid_t pid = spawn({binary("cosim").string(), "run", job.string(), "--output",
                           (dir / "stopped").string(), "--checkpoint-every", "100000"},
                          dir / "stopped.log");
  (void)wait_for_pid_file(dir / "stopped" / "right" / "pid", std::chrono::seconds(60));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ::kill(pid, SIGTERM);
  StoppedRun stopped{wait_for(pid, dir / "stopped.log", std::chrono::seconds(120))};
  const auto names = checkpoints_in(dir / "stopped");
  EXPECT_EQ(names.size(), 1u) << stopped.result.output;
  if (names.size() == 1)
    stopped.window = std::stoul(names[0].substr(std::string("window_").size()));
  return stopped;
}

}  // namespace cosim::testing
