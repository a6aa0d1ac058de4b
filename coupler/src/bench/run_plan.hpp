#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bench/suite.hpp"

namespace cosim::bench {

struct BenchOptions {
  std::filesystem::path suite_file;
  std::filesystem::path output;
  Resolution resolution = Resolution::coarse;
  std::vector<std::string> only;  // scenario names; empty: all
  int jobs = 1;
};

// One run of a suite: a scenario with one backend (at one level of its
// refinement study), its inputs written into its own directory
//   <output>/runs/<scenario>/<backend>[--<level>]/input/
// and the command that runs it (its outputs go to .../out/).
struct PlannedRun {
  const Scenario* scenario = nullptr;
  const BackendRuns* backend = nullptr;
  const Level* level = nullptr;  // nullptr: the backend has no refinement study
  std::filesystem::path directory;
  std::string executable;         // resolved next to cosim, then on PATH
  std::vector<std::string> args;  // without argv[0]
  bool coupled = false;           // run by `cosim run`
  std::string key;                // hash of every input's contents
  double end_time = 0.0;          // simulated [s], for progress

  std::filesystem::path output() const { return directory / "out"; }
  // scenario/backend or scenario/backend@level, for messages.
  std::string id() const;
  std::string backend_name() const { return backend->backend->name; }
  std::string level_label() const;
};

// The runs the options select, in suite order, with their inputs written.
// Throws InputError when --only names no scenario of the suite, or when an
// input cannot be built (located at the suite's key).
std::vector<PlannedRun> plan_runs(const Suite& suite, const BenchOptions& options);

// A label as a directory name: letters, digits, '-', '_' and '.' kept,
// anything else '_'.
std::string directory_name(const std::string& label);

}  // namespace cosim::bench
