#pragma once

#include <filesystem>
#include <optional>
#include <string>

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
};

std::string control_dict(const ControlSettings& settings);

// Whether `interval` is a whole number of fixed steps `step` (to a relative
// 1e-9): every window and output time must fall on a step.
bool is_whole_number_of_steps(double interval, double step);
// Writes system/controlDict atomically (a half-written one must never be
// read by a solver start).
void write_control_dict(const std::filesystem::path& case_dir, const ControlSettings& settings);

}  // namespace openfoam
