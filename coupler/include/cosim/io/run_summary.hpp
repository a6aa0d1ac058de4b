#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cosim/exit_codes.hpp"
#include "cosim/io/phase_timer.hpp"

namespace cosim {

// The record every run leaves in `<dir>/summary.json` (architecture.md §6): what
// ran, on which config, how far it got, where the wall time went, how well
// the conserved totals held and the run's own metrics. `write()` replaces the
// file atomically and may be called as often as wanted (e.g. every N
// windows), so a run that dies still leaves a valid summary of its progress
// with status "running"; `finish()` records the exit status and writes.
//
// Layout (keys stable; tests and `cosim bench` read them):
//   program, version, config {path, hash}, status {state, exit_code, message},
//   started_at, updated_at, finished_at (ISO 8601 UTC; finished_at null until
//   finish), steps, windows, wall_time_s {total, phases {name: s}},
//   conserved {name: {unit, start, end, relative_change}},
//   metrics {name: {value, unit}}, progress {simulated_time_s, end_time_s}
//   (null until set), plus any sections added with set_section.
class RunSummary {
 public:
  RunSummary(std::filesystem::path output_dir, std::string program);

  void set_config(const std::filesystem::path& config_path, std::uint64_t config_hash);
  void set_steps(std::int64_t steps) { steps_ = steps; }
  void set_windows(std::int64_t windows) { windows_ = windows; }
  std::int64_t windows() const { return windows_; }
  // How far the simulation has got, for whoever watches the run (`cosim bench`).
  void set_progress(double simulated_time, double end_time) {
    simulated_time_ = simulated_time;
    end_time_ = end_time;
  }
  void set_conserved_start(const std::string& name, double value, const std::string& unit);
  void set_conserved_end(const std::string& name, double value, const std::string& unit);
  void set_metric(const std::string& name, double value, const std::string& unit);
  // A free-form top-level section (e.g. "participants"); the reserved keys
  // listed above are refused with InputError.
  void set_section(const std::string& key, nlohmann::json value);

  // Wall time per phase; reported under wall_time_s.phases.
  PhaseTimer& phases() { return phases_; }
  const PhaseTimer& phases() const { return phases_; }

  nlohmann::json to_json() const;
  void write() const;
  void finish(ExitCode code, const std::string& message);

  const std::filesystem::path& path() const { return path_; }

 private:
  struct Conserved {
    std::string unit;
    std::optional<double> start;
    std::optional<double> end;
  };
  struct Metric {
    double value;
    std::string unit;
  };

  std::filesystem::path path_;
  std::string program_;
  std::string config_path_;
  std::optional<std::uint64_t> config_hash_;
  std::chrono::system_clock::time_point started_at_;
  std::chrono::steady_clock::time_point started_steady_;
  std::optional<std::chrono::system_clock::time_point> finished_at_;
  std::optional<std::chrono::steady_clock::time_point> finished_steady_;
  std::optional<ExitCode> exit_code_;
  std::string message_;
  std::int64_t steps_ = 0;
  std::int64_t windows_ = 0;
  std::optional<double> simulated_time_;
  std::optional<double> end_time_;
  std::map<std::string, Conserved> conserved_;
  std::map<std::string, Metric> metrics_;
  std::map<std::string, nlohmann::json> sections_;
  PhaseTimer phases_;
};

// Runs `body` and finishes the summary with its outcome: success
// ("completed"), the exit code of a cosim::Error, or internal_error for any
// other exception; errors are logged. Returns the process exit code.
int run_and_finish(RunSummary& summary, const std::function<void()>& body);

// Which record of a run another process may overrule.
enum class Overrule {
  nothing,   // only a record still "running" (the run could not finish it)
  success,   // also a success (a coupled run that failed after this part ended)
  anything,  // also a failure it recorded (it blamed the wrong cause)
};

// Records in the summary.json at `path` that its run failed, when the run
// could not say so itself (killed by a signal, ended by an MPI abort): a
// state "running", or a finished one that `overrule` allows, becomes
// finished with `code` and `message`; the rest is kept. Returns whether it
// changed the file.
bool record_failure_in_summary(const std::filesystem::path& path, ExitCode code,
                               const std::string& message, Overrule overrule = Overrule::nothing);

// ISO 8601 UTC with milliseconds, e.g. "2024-05-01T12:34:56.789Z".
std::string iso8601_utc(std::chrono::system_clock::time_point time);

}  // namespace cosim
