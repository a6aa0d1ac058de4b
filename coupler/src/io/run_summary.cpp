#include "cosim/io/run_summary.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <array>
#include <cmath>
#include <ctime>
#include <fstream>
#include <utility>

#include "cosim/error.hpp"
#include "cosim/io/content_hash.hpp"
#include "cosim/io/files.hpp"

namespace cosim {

namespace {

constexpr std::array reserved_keys{"program",    "version",     "config",  "status",  "started_at",
                                   "updated_at", "finished_at", "steps",   "windows", "wall_time_s",
                                   "conserved",  "metrics",     "progress"};

nlohmann::json optional_number(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

}  // namespace

int run_and_finish(RunSummary& summary, const std::function<void()>& body) {
  try {
    body();
  } catch (const Error& e) {
    spdlog::error("{}", e.what());
    summary.finish(e.code(), e.what());
    return to_int(e.code());
  } catch (const std::exception& e) {
    spdlog::critical("internal error: {}", e.what());
    summary.finish(ExitCode::internal_error, std::string("internal error: ") + e.what());
    return to_int(ExitCode::internal_error);
  }
  summary.finish(ExitCode::success, "completed");
  return to_int(ExitCode::success);
}

std::string iso8601_utc(std::chrono::system_clock::time_point time) {
  using namespace std::chrono;
  const auto since_epoch = time.time_since_epoch();
  const auto whole_seconds = floor<seconds>(since_epoch);
  const auto millis = duration_cast<milliseconds>(since_epoch - whole_seconds).count();
  const std::time_t t = system_clock::to_time_t(system_clock::time_point(whole_seconds));
  std::tm utc{};
  gmtime_r(&t, &utc);
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}.{:03}Z", utc.tm_year + 1900,
                     utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, millis);
}

RunSummary::RunSummary(std::filesystem::path output_dir, std::string program)
    : path_(output_dir / "summary.json"),
      program_(std::move(program)),
      started_at_(std::chrono::system_clock::now()),
      started_steady_(std::chrono::steady_clock::now()) {
  create_output_directory(output_dir);
}

void RunSummary::set_config(const std::filesystem::path& config_path, std::uint64_t config_hash) {
  config_path_ = config_path.string();
  config_hash_ = config_hash;
}

void RunSummary::set_conserved_start(const std::string& name, double value,
                                     const std::string& unit) {
  Conserved& c = conserved_[name];
  c.unit = unit;
  c.start = value;
}

void RunSummary::set_conserved_end(const std::string& name, double value, const std::string& unit) {
  Conserved& c = conserved_[name];
  c.unit = unit;
  c.end = value;
}

void RunSummary::set_metric(const std::string& name, double value, const std::string& unit) {
  metrics_[name] = Metric{value, unit};
}

void RunSummary::set_section(const std::string& key, nlohmann::json value) {
  for (const char* reserved : reserved_keys)
    if (key == reserved)
      throw InputError("summary section '" + key + "' is reserved for the run summary itself");
  sections_[key] = std::move(value);
}

nlohmann::json RunSummary::to_json() const {
  using nlohmann::json;
  json j = json::object();
  for (const auto& [key, value] : sections_) j[key] = value;
  j["program"] = program_;
  j["version"] = COSIM_VERSION;
  j["config"] = {{"path", config_path_},
                 {"hash", config_hash_ ? json(to_hex16(*config_hash_)) : json(nullptr)}};
  j["status"] = {{"state", exit_code_ ? "finished" : "running"},
                 {"exit_code", exit_code_ ? json(to_int(*exit_code_)) : json(nullptr)},
                 {"exit_status", exit_code_ ? json(to_string(*exit_code_)) : json(nullptr)},
                 {"message", message_}};
  j["started_at"] = iso8601_utc(started_at_);
  j["updated_at"] = iso8601_utc(std::chrono::system_clock::now());
  j["finished_at"] = finished_at_ ? json(iso8601_utc(*finished_at_)) : json(nullptr);
  j["steps"] = steps_;
  j["windows"] = windows_;
  j["progress"] = {{"simulated_time_s", optional_number(simulated_time_)},
                   {"end_time_s", optional_number(end_time_)}};

  json phases = json::object();
  for (const auto& [phase, seconds] : phases_.phases()) phases[phase] = seconds;
  const auto wall_end = finished_steady_.value_or(std::chrono::steady_clock::now());
  const double total = std::chrono::duration<double>(wall_end - started_steady_).count();
  j["wall_time_s"] = {{"total", total}, {"phases", phases}};

  json conserved = json::object();
  for (const auto& [name, c] : conserved_) {
    json relative_change = nullptr;
    if (c.start && c.end && *c.start != 0.0)
      relative_change = (*c.end - *c.start) / std::abs(*c.start);
    conserved[name] = {{"unit", c.unit},
                       {"start", optional_number(c.start)},
                       {"end", optional_number(c.end)},
                       {"relative_change", relative_change}};
  }
  j["conserved"] = conserved;

  json metrics = json::object();
  for (const auto& [name, m] : metrics_) metrics[name] = {{"value", m.value}, {"unit", m.unit}};
  j["metrics"] = metrics;
  return j;
}

void RunSummary::write() const {
  write_file_atomically(
      path_, to_json().dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

bool record_failure_in_summary(const std::filesystem::path& path, ExitCode code,
                               const std::string& message, Overrule overrule) {
  nlohmann::json j;
  try {
    std::ifstream in(path);
    if (!in) return false;
    j = nlohmann::json::parse(in);
    const auto& status = j.at("status");
    const bool running = status.at("state") == "running";
    const bool succeeded = !running && status.at("exit_code") == 0;
    if (!running && overrule == Overrule::nothing) return false;
    if (!running && !succeeded && overrule == Overrule::success) return false;
  } catch (const std::exception&) {
    return false;
  }
  const std::string now = iso8601_utc(std::chrono::system_clock::now());
  j["status"] = {{"state", "finished"},
                 {"exit_code", to_int(code)},
                 {"exit_status", to_string(code)},
                 {"message", message}};
  j["updated_at"] = now;
  j["finished_at"] = now;
  write_file_atomically(path,
                        j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  return true;
}

void RunSummary::finish(ExitCode code, const std::string& message) {
  exit_code_ = code;
  message_ = message;
  finished_at_ = std::chrono::system_clock::now();
  finished_steady_ = std::chrono::steady_clock::now();
  write();
}

}  // namespace cosim
