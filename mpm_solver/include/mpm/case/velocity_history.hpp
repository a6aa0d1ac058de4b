#pragma once

#include <filesystem>
#include <string_view>

#include "cosim/config/node.hpp"
#include "mpm/case/case_description.hpp"

namespace mpm {

// A prescribed velocity history: a CSV file with the header
// `time [s],vx [m/s],vy [m/s]` (3D: `,vz [m/s]`) and one row per time,
// times strictly increasing. Errors are InputErrors located at the CSV line
// and column, naming `key` (the YAML key that gave the file).
TimeSeries read_velocity_history(const std::filesystem::path& file, int dimension,
                                 const cosim::config::Node& key);
TimeSeries parse_velocity_history(std::string_view text, const std::filesystem::path& file,
                                  int dimension, const std::string& key_path);

}  // namespace mpm
