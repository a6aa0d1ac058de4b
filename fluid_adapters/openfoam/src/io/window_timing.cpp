#include "openfoam/io/window_timing.hpp"

namespace openfoam {

nlohmann::json windows_json(const std::vector<WindowTiming>& windows, long steps_per_window) {
  nlohmann::json w = {{"end_time_s", nlohmann::json::array()},
                      {"adapter_write_s", nlohmann::json::array()},
                      {"solver_startup_s", nlohmann::json::array()},
                      {"solver_stepping_s", nlohmann::json::array()},
                      {"field_read_s", nlohmann::json::array()}};
  for (const WindowTiming& t : windows) {
    w["end_time_s"].push_back(t.end_time);
    w["adapter_write_s"].push_back(t.write);
    w["solver_startup_s"].push_back(t.solver.startup);
    w["solver_stepping_s"].push_back(t.solver.stepping);
    w["field_read_s"].push_back(t.read);
  }
  w["steps_per_window"] = steps_per_window;
  return w;
}

}  // namespace openfoam
