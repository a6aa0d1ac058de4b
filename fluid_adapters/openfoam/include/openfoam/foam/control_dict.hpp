#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

namespace openfoam {

// OpenFOAM's time-directory names use `timeFormat general` with this many
// significant digits (time_name must use the same).
inline constexpr int time_precision = 10;

// What system/controlDict says for one start of the solver: from the latest
// time directory to `end_time` in fixed steps, writing every field at the
// end (every `write_every` steps), ASCII with enough digits that a restart
// loses nothing the solver did not already round.
struct ControlSettings {
  std::string application;
  double end_time = 0.0;
  double time_step = 0.0;
  long write_every = 1;  // steps
  // When set, the mixture density `rho` alone is also written at this time
  // (MPPICInterFoam: the step before the window's end; see
  // restart_inertia.hpp).
  std::optional<double> write_density_at;
  // When set, the pressure `p` and the cloud's momentum source
  // `kinematicCloud:UTrans` alone are also written at every step from the
  // first to the last of these times (the window's steps before its end:
  // the adapter sends their means over the window, window_step_means.hpp).
  std::optional<std::pair<double, double>> write_steps_between;
};

std::string control_dict(const ControlSettings& settings);

// Whether `interval` is a whole number of fixed steps `step` (to a relative
// 1e-9): every window and output time must fall on a step.
bool is_whole_number_of_steps(double interval, double step);
// Writes system/controlDict atomically (a half-written one must never be
// read by a solver start).
void write_control_dict(const std::filesystem::path& case_dir, const ControlSettings& settings);

}  // namespace openfoam
