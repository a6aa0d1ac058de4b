#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/io/run_size.hpp"
#include "cosim/participant.hpp"

namespace cosim {

// What every solver executable takes on its command line (architecture.md §6):
//   <program> --config case.yaml --output dir [--overwrite] [--threads N] [--verbosity V]
//   <program> --validate --config case.yaml
//   <program> --help-config
// plus the coupling options `cosim run` adds (add_coupling_options).
struct SolverCommandLine {
  std::filesystem::path config;
  std::filesystem::path output;
  int threads = -1;  // < 0: the case's own `threads`
  Verbosity verbosity = Verbosity::normal;
  CouplingEndpoint endpoint;
  // What the run does with a non-empty --output: refuse (the default),
  // overwrite (--overwrite), or, started by `cosim run`, use the directory
  // the coupler prepared (prepared).
  OutputReuse reuse = OutputReuse::refuse;
};

// A case file that loaded and passed every check: its name and the size of
// its run.
struct ValidatedCase {
  std::string name;
  RunSize size;
  std::string kind = {};  // when the program reads more than its case_kind
};

struct SolverProgram {
  std::string name;                                  // e.g. "swe_fluid", used in messages
  std::string description;                           // the --help title
  std::string case_kind;                             // e.g. "swe_case"
  std::function<std::string()> help_config;          // the case file's keys
  std::function<int(const SolverCommandLine&)> run;  // returns the exit code
  // Loads and checks the case file as `run` would (schema, values, size
  // against its limits), touching nothing; throws InputError when it cannot run.
  std::function<ValidatedCase(const std::filesystem::path& config)> validate;
};

// Parses the command line, prints the keys for --help-config, checks the
// case for --validate (printing "<config>: valid <kind> '<name>': <size>"),
// or runs the program; a cosim::Error becomes its exit code and any other
// exception internal_error, each reported as "<name>: error: ..." on stderr.
int run_solver_program(const SolverProgram& program, int argc, char** argv);

}  // namespace cosim
