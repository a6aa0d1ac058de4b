#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "cosim/io/logging.hpp"
#include "cosim/participant.hpp"

namespace cosim {

// What every solver executable takes on its command line (DESIGN.md §6):
//   <program> --config case.yaml --output dir [--threads N] [--verbosity V]
//   <program> --help-config
// plus the coupling options `cosim run` adds (add_coupling_options).
struct SolverCommandLine {
  std::filesystem::path config;
  std::filesystem::path output;
  int threads = -1;  // < 0: the case's own `threads`
  Verbosity verbosity = Verbosity::normal;
  CouplingEndpoint endpoint;
};

struct SolverProgram {
  std::string name;         // e.g. "swe_fluid", used in messages
  std::string description;  // the --help title
  std::string case_kind;    // e.g. "swe_case"
  std::function<std::string()> help_config;                 // the case file's keys
  std::function<int(const SolverCommandLine&)> run;         // returns the exit code
};

// Parses the command line, prints the keys for --help-config, or runs the
// program; a cosim::Error becomes its exit code and any other exception
// internal_error, each reported as "<name>: error: ..." on stderr.
int run_solver_program(const SolverProgram& program, int argc, char** argv);

}  // namespace cosim
