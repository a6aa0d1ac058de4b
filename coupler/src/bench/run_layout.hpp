#pragma once

#include <filesystem>
#include <string>

#include "bench/backend_descriptor.hpp"

namespace cosim::bench {

// Where a finished run's participants wrote. How its backend names what the
// bench reads (gauge columns, snapshot files and fields) is in the backend's
// descriptor: the bench speaks one language over the backends.
struct RunLayout {
  const BackendDescriptor* backend = nullptr;
  bool coupled = false;
  std::filesystem::path input;   // the run's input/ directory
  std::filesystem::path output;  // the run's out/ directory

  // A participant's directory; standalone runs have only the output itself.
  std::filesystem::path participant(const std::string& name) const;
  // The fluid's directory (coupled: its participant's, `water` unless given).
  std::filesystem::path fluid(const std::string& name = {}) const;
  // The MPM case the run used: a standalone run's input/case.yaml, or the
  // config the run's job gives the participant.
  std::filesystem::path soil_case(const std::string& participant) const;
};

}  // namespace cosim::bench
