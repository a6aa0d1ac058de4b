#include "cosim/solver_command_line.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "cosim/error.hpp"
#include "cosim/runtime/stop_request.hpp"

namespace cosim {

namespace {

int validate(const SolverProgram& program, const SolverCommandLine& line) {
  if (line.config.empty()) throw InputError("--validate needs --config <case.yaml>");
  if (!program.validate) throw InputError(program.name + " cannot --validate");
  const ValidatedCase valid = program.validate(line.config);
  std::cout << fmt::format("{}: valid {} '{}': {}\n", line.config.string(),
                           valid.kind.empty() ? program.case_kind : valid.kind, valid.name,
                           valid.size.describe());
  return 0;
}

}  // namespace

int run_solver_program(const SolverProgram& program, int argc, char** argv) {
  // SIGTERM, SIGINT and SIGHUP end a run between steps with its record
  // written (`cosim` stops its participants with SIGTERM).
  runtime::install_stop_handlers();
  CLI::App app{program.description};
  bool help_config = false;
  bool check_only = false;
  bool overwrite = false;
  std::string verbosity = "normal";
  SolverCommandLine line;
  app.add_flag("--help-config", help_config,
               "list every key of a case file (kind: " + program.case_kind + ") and exit");
  app.add_flag("--validate", check_only,
               "check the case file (keys, values, the run's estimated size against its limits) "
               "without running; prints one line and exits 0, or the error and exits 2");
  app.add_option("-c,--config", line.config,
                 "the case's YAML file (kind: " + program.case_kind + ")");
  app.add_option("-o,--output", line.output, "run directory (refused when it is not empty)");
  app.add_flag("--overwrite", overwrite,
               "clear the earlier run an --output directory holds, then run afresh");
  app.add_option("--threads", line.threads, "OpenMP threads (default: the case's `threads`)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--verbosity", verbosity, "quiet | normal | verbose | trace");
  add_coupling_options(app, line.endpoint);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : to_int(ExitCode::bad_input);
  }
  try {
    if (help_config) {
      std::cout << program.help_config();
      return 0;
    }
    if (check_only) return validate(program, line);
    if (line.config.empty() || line.output.empty())
      throw InputError("--config and --output are required (or --help-config, or --validate)");
    line.verbosity = parse_verbosity(verbosity);
    // `cosim run` made the run directory and writes the console there.
    line.reuse = !line.endpoint.is_standalone() ? OutputReuse::prepared
                 : overwrite                    ? OutputReuse::overwrite
                                                : OutputReuse::refuse;
    if (line.reuse == OutputReuse::overwrite && is_inside(line.config, line.output))
      throw InputError(fmt::format("--overwrite would clear '{}', which holds the case file '{}'",
                                   line.output.string(), line.config.string()));
    return program.run(line);
  } catch (const Error& e) {
    std::cerr << program.name << ": error: " << e.what() << "\n";
    return to_int(e.code());
  } catch (const std::exception& e) {
    std::cerr << program.name << ": internal error: " << e.what() << "\n";
    return to_int(ExitCode::internal_error);
  }
}

}  // namespace cosim
