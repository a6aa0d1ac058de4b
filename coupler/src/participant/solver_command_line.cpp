#include "cosim/solver_command_line.hpp"

#include <CLI/CLI.hpp>
#include <iostream>

#include "cosim/error.hpp"

namespace cosim {

int run_solver_program(const SolverProgram& program, int argc, char** argv) {
  CLI::App app{program.description};
  bool help_config = false;
  std::string verbosity = "normal";
  SolverCommandLine line;
  app.add_flag("--help-config", help_config,
               "list every key of a case file (kind: " + program.case_kind + ") and exit");
  app.add_option("-c,--config", line.config, "the case's YAML file (kind: " + program.case_kind + ")");
  app.add_option("-o,--output", line.output, "run directory");
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
    if (line.config.empty() || line.output.empty())
      throw InputError("--config and --output are required (or --help-config)");
    line.verbosity = parse_verbosity(verbosity);
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
