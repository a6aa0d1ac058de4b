#include "openfoam/foam/time_directories.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

#include "cosim/error.hpp"

namespace openfoam {

namespace {

namespace fs = std::filesystem;

std::optional<double> time_of(const std::string& name) {
  double time = 0.0;
  const char* end = name.data() + name.size();
  const auto [stop, error] = std::from_chars(name.data(), end, time);
  if (name.empty() || error != std::errc() || stop != end || !std::isfinite(time)) {
    return std::nullopt;
  }
  return time;
}

}  // namespace

std::string time_name(double time, int precision) {
  return fmt::format("{:.{}g}", time, precision);
}

std::vector<TimeDirectory> time_directories(const fs::path& case_directory) {
  std::vector<TimeDirectory> found;
  std::error_code ec;
  for (fs::directory_iterator it(case_directory, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code not_a_directory;
    if (!it->is_directory(not_a_directory)) continue;
    std::string name = it->path().filename().string();
    if (const std::optional<double> time = time_of(name)) found.push_back({*time, std::move(name)});
  }
  if (ec) {
    throw cosim::Error(cosim::ExitCode::participant_failed,
                       fmt::format("cannot list the time directories of OpenFOAM case '{}': {}",
                                   case_directory.string(), ec.message()));
  }
  // By name after time, so that `0.1` and `0.10` come in a fixed order.
  std::sort(found.begin(), found.end(), [](const TimeDirectory& a, const TimeDirectory& b) {
    return a.time != b.time ? a.time < b.time : a.name < b.name;
  });
  return found;
}

std::optional<TimeDirectory> latest_time_directory(const fs::path& case_directory) {
  std::vector<TimeDirectory> all = time_directories(case_directory);
  if (all.empty()) return std::nullopt;
  return std::move(all.back());
}

std::vector<TimeDirectory> remove_time_directories_except(const fs::path& case_directory,
                                                          std::span<const std::string> keep) {
  std::vector<TimeDirectory> removed;
  for (TimeDirectory& directory : time_directories(case_directory)) {
    if (std::find(keep.begin(), keep.end(), directory.name) != keep.end()) continue;
    std::error_code ec;
    fs::remove_all(case_directory / directory.name, ec);
    if (ec) {
      throw cosim::Error(cosim::ExitCode::participant_failed,
                         fmt::format("cannot remove time directory '{}': {}",
                                     (case_directory / directory.name).string(), ec.message()));
    }
    removed.push_back(std::move(directory));
  }
  return removed;
}

}  // namespace openfoam
