#include "bench/runner.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <deque>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "cosim/io/files.hpp"
#include "cosim/io/tail_lines.hpp"
#include "cosim/runtime/supervisor.hpp"

namespace cosim::bench {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

fs::path record_path(const PlannedRun& run) {
  return run.directory / "bench_run.json";
}

void write_record(const PlannedRun& run, const RunRecord& r) {
  const nlohmann::json j{
      {"run", run.id()},
      {"key", r.key},
      {"state", r.state},
      {"exit_code", r.exit_code},
      {"wall_time_s", r.wall_time_s},
      {"message", r.message},
      {"command", fmt::format("{} {}", run.executable, fmt::join(run.args, " "))}};
  write_file_atomically(record_path(run), j.dump(2) + "\n");
}

std::string clock_text(double seconds) {
  const auto s = static_cast<long>(seconds + 0.5);
  return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}

// The simulated time a run has reached, from its summary.json (coupled runs:
// the coupler's).
std::optional<double> simulated_time(const PlannedRun& run) {
  std::ifstream in(run.output() / "summary.json");
  if (!in) return std::nullopt;
  try {
    const auto j = nlohmann::json::parse(in);
    const auto& t = j.at("progress").at("simulated_time_s");
    if (t.is_number()) return t.get<double>();
  } catch (const std::exception&) {
    // Being replaced at this moment, or written by an older version.
  }
  return std::nullopt;
}

// The wall time a run measured itself (its summary.json), finer than the
// runner's polling.
std::optional<double> own_wall_time(const PlannedRun& run) {
  std::ifstream in(run.output() / "summary.json");
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in).at("wall_time_s").at("total").get<double>();
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

struct Active {
  std::size_t index = 0;
  Clock::time_point started;
};

// Why a run failed: its exit and the last lines of its console.
std::string failure_message(const PlannedRun& run, const runtime::ChildExit& e) {
  std::string text = fmt::format("{} {}", run.executable, e.describe());
  const auto lines = tail_lines(run.directory / "console.log", 6);
  for (const auto& line : lines)
    if (!line.empty()) text += "\n    " + line;
  return text;
}

class Display {
 public:
  Display(std::size_t total, bool terminal) : total_(total), terminal_(terminal) {}

  void show(const std::vector<PlannedRun>& runs, const std::map<pid_t, Active>& active,
            std::size_t done) {
    const auto now = Clock::now();
    if (now - last_ < (terminal_ ? std::chrono::milliseconds(500) : std::chrono::seconds(10)))
      return;
    last_ = now;
    std::string line = fmt::format("[{}/{} done]", done, total_);
    for (const auto& [pid, a] : active) {
      const PlannedRun& run = runs[a.index];
      const double wall = std::chrono::duration<double>(now - a.started).count();
      const auto t = simulated_time(run);
      if (t && run.end_time > 0.0 && *t > 0.0) {
        const double done_share = std::min(*t / run.end_time, 1.0);
        line += fmt::format("  {} t = {:.4g}/{:.4g} s ETA {}", run.id(), *t, run.end_time,
                            clock_text(wall * (1.0 - done_share) / done_share));
      } else {
        line += fmt::format("  {} starting ({})", run.id(), clock_text(wall));
      }
    }
    if (terminal_) {
      std::fprintf(stderr, "\r%s\033[K", line.c_str());
      std::fflush(stderr);
    } else {
      spdlog::info("{}", line);
    }
  }

  void event(const std::string& text) {
    if (terminal_) std::fprintf(stderr, "\r\033[K");
    spdlog::info("{}", text);
  }

  void finish() {
    if (terminal_) std::fprintf(stderr, "\r\033[K");
  }

 private:
  std::size_t total_;
  bool terminal_;
  Clock::time_point last_{};
};

}  // namespace

RunRecord read_record(const PlannedRun& run) {
  RunRecord r;
  std::ifstream in(record_path(run));
  if (!in) return r;
  try {
    const auto j = nlohmann::json::parse(in);
    r.key = j.at("key").get<std::string>();
    r.state = j.at("state").get<std::string>();
    r.exit_code = j.at("exit_code").get<int>();
    r.wall_time_s = j.at("wall_time_s").get<double>();
    r.message = j.at("message").get<std::string>();
  } catch (const std::exception&) {
    return RunRecord{};
  }
  return r;
}

std::vector<RunRecord> run_all(const std::vector<PlannedRun>& runs, const RunnerOptions& options) {
  std::vector<RunRecord> records(runs.size());
  std::deque<std::size_t> pending;
  std::size_t done = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    RunRecord previous = read_record(runs[i]);
    if (previous.completed() && previous.key == runs[i].key) {
      previous.reused = true;
      records[i] = previous;
      ++done;
      spdlog::info("{}: finished by an earlier run with the same inputs (key {}); kept",
                   runs[i].id(), previous.key);
      continue;
    }
    records[i].key = runs[i].key;
    pending.push_back(i);
  }

  Display display(runs.size(), options.terminal);
  runtime::Supervisor supervisor;
  std::map<pid_t, Active> active;
  const auto interrupted = [&] {
    return options.interrupted != nullptr && options.interrupted->load();
  };
  const auto finish = [&](std::size_t i, const runtime::ChildExit& e, Clock::time_point started) {
    RunRecord& r = records[i];
    r.wall_time_s = own_wall_time(runs[i]).value_or(
        std::chrono::duration<double>(Clock::now() - started).count());
    r.exit_code = e.signal != 0 ? 128 + e.signal : e.exit_status;
    r.state = e.success() ? "completed" : (interrupted() ? "interrupted" : "failed");
    if (!e.success()) r.message = failure_message(runs[i], e);
    write_record(runs[i], r);
    ++done;
    display.event(fmt::format("{}: {} in {:.1f} s{}", runs[i].id(), r.state, r.wall_time_s,
                              r.completed() ? "" : ": " + r.message));
  };

  while ((!pending.empty() || !active.empty())) {
    while (!interrupted() && !pending.empty() &&
           active.size() < static_cast<std::size_t>(std::max(options.jobs, 1))) {
      const std::size_t i = pending.front();
      pending.pop_front();
      const PlannedRun& run = runs[i];
      // A fresh output: nothing of an earlier attempt with other inputs stays.
      std::error_code ec;
      fs::remove_all(run.output(), ec);
      fs::remove(record_path(run), ec);
      fs::remove(run.directory / "console.log", ec);
      runtime::ChildSpec child;
      child.name = run.id();
      child.args = run.args;
      child.log_file = run.directory / "console.log";
      try {
        child.executable = runtime::resolve_executable(run.executable, run.directory);
        const pid_t pid = supervisor.start(child);
        active[pid] = {i, Clock::now()};
        display.event(
            fmt::format("{}: started ({} {})", run.id(), run.executable, fmt::join(run.args, " ")));
      } catch (const std::exception& e) {
        records[i].state = "failed";
        records[i].exit_code = to_int(ExitCode::bad_input);
        records[i].message = e.what();
        write_record(run, records[i]);
        ++done;
        display.event(fmt::format("{}: failed to start: {}", run.id(), e.what()));
      }
    }
    if (interrupted()) {
      for (const auto& e : supervisor.stop_all(std::chrono::milliseconds(3000))) {
        auto it = active.find(e.pid);
        if (it == active.end()) continue;
        finish(it->second.index, e, it->second.started);
        records[it->second.index].state = "interrupted";
        write_record(runs[it->second.index], records[it->second.index]);
        active.erase(it);
      }
      for (std::size_t i : pending) records[i].state = "interrupted";
      pending.clear();
      break;
    }
    for (const auto& e : supervisor.reap()) {
      auto it = active.find(e.pid);
      if (it == active.end()) continue;
      finish(it->second.index, e, it->second.started);
      active.erase(it);
    }
    display.show(runs, active, done);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  display.finish();
  return records;
}

}  // namespace cosim::bench
