#pragma once

#include <filesystem>
#include <string>

#include "bench/suite.hpp"

namespace cosim::bench {

// Where a finished run's participants wrote, and how its backend names what
// the bench reads (gauge columns, snapshot files and fields): the backends
// grew their own conventions, the bench speaks one language over them.
struct RunLayout {
  Backend backend = Backend::ice;
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

// The header of a gauge's column in the backend's gauges.csv (mpm:
// probes.csv). Throws Error when the backend does not record the variable.
std::string gauge_column(Backend backend, const std::string& gauge, const std::string& variable);
std::string gauge_file(Backend backend);

// The base name of the backend's field snapshots (ice, openfoam, swe,
// particles).
std::string snapshot_base(Backend backend);

// A field of the bench's vocabulary as the backend stores it.
struct StoredField {
  std::string dataset;
  int component = 0;
};
StoredField stored_field(Backend backend, const std::string& field);

}  // namespace cosim::bench
