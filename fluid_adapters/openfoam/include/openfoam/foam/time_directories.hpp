#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

// The time directories of an OpenFOAM case (`0`, `0.05`, `1e-05`, ...):
// where the solver reads its start state and writes each output time.
namespace openfoam {

struct TimeDirectory {
  double time = 0.0;
  std::string name;  // as on disk
};

// OpenFOAM's directory name for `time` under `timeFormat general;
// timePrecision <precision>`: printf's %.<precision>g (0.05 -> "0.05",
// 1e-05 -> "1e-05", 2 -> "2"). OpenFOAM raises the precision by itself when
// two output times would share a name, so prefer listing what it wrote.
std::string time_name(double time, int precision);

// The directories of `case_directory` whose whole name reads as a finite
// number, `0` included, sorted by time (constant, system, processor0, 0.orig
// are not time directories). Throws cosim::Error(participant_failed) when the
// case cannot be listed.
std::vector<TimeDirectory> time_directories(const std::filesystem::path& case_directory);

// The last of time_directories(), none when there is none.
std::optional<TimeDirectory> latest_time_directory(const std::filesystem::path& case_directory);

// Removes every time directory of `case_directory` not named in `keep` (keep
// "0" to keep the initial state); returns those removed. Throws
// cosim::Error(participant_failed) naming the directory that cannot go.
std::vector<TimeDirectory> remove_time_directories_except(
    const std::filesystem::path& case_directory, std::span<const std::string> keep);

}  // namespace openfoam
