#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "openfoam/foam/foam_application.hpp"

namespace openfoam {

// The cost of one window [s].
struct WindowTiming {
  double end_time = 0.0;
  double write = 0.0;  // the adapter's files before the start
  ApplicationTiming solver;
  double read = 0.0;  // the fields read back
};

// The summary's `openfoam_windows` section: each cost as a column of one
// value per window, and the steps per window.
nlohmann::json windows_json(const std::vector<WindowTiming>& windows, long steps_per_window);

}  // namespace openfoam
