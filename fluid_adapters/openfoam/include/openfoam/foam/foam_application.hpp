#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "openfoam/foam/installation.hpp"

namespace openfoam {

// Wall time of one run of an OpenFOAM application [s].
struct ApplicationTiming {
  double startup = 0.0;   // launch to its first time step (the first "Time = " line)
  double stepping = 0.0;  // from there to its exit, the last write included
  double total = 0.0;
};

// Runs the OpenFOAM application `name` on `case_dir` (`-case` is added to
// `arguments`) to completion, its output in `log_file`, in its own process
// group that dies with the adapter. A non-zero exit, a signal or a
// "FOAM FATAL" line in its log throws cosim::Error (participant_failed,
// exit 3) naming the application, how it ended, the case directory (kept
// for inspection) and the last lines of its log. With `processes` > 1 it
// runs decomposed under `mpirun -np <processes>` (found on PATH like the
// applications) with `-parallel`; as root the Open MPI variables that allow
// it are set. A run that outlives `timeout` is stopped (SIGTERM, then
// SIGKILL) and throws the same error saying so.
ApplicationTiming run_application(const Installation& installation, const std::string& name,
                                  std::vector<std::string> arguments,
                                  const std::filesystem::path& case_dir,
                                  const std::filesystem::path& log_file, int processes = 1,
                                  std::chrono::seconds timeout = std::chrono::hours(24));

// Runs a (serial, short) application as run_application does and returns
// what it wrote to `log_file` in this run: the report of checkMesh, the
// value foamDictionary prints.
std::string application_output(const Installation& installation, const std::string& name,
                               std::vector<std::string> arguments,
                               const std::filesystem::path& case_dir,
                               const std::filesystem::path& log_file);

}  // namespace openfoam
