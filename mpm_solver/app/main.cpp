// mpm_solver: the explicit material point method, standalone or as a
// participant of a coupled job (`cosim run`).
//
//   mpm_solver --config case.yaml --output run/ [--threads N]
//   mpm_solver --help-config

#include <CLI/CLI.hpp>
#include <iostream>

#include "cosim/error.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/participant.hpp"
#include "mpm/case/case_schema.hpp"
#include "mpm/coupling/coupling_observer.hpp"
#include "mpm/io/run_driver.hpp"

int main(int argc, char** argv) {
  CLI::App app{"mpm_solver: explicit material point method for soil and structures"};
  bool help_config = false;
  std::string verbosity = "normal";
  mpm::RunOptions options;
  cosim::CouplingEndpoint endpoint;
  app.add_flag("--help-config", help_config, "list every key of a case file (kind: mpm_case) and exit");
  app.add_option("-c,--config", options.config, "the case's YAML file (kind: mpm_case)");
  app.add_option("-o,--output", options.output, "run directory");
  app.add_option("--threads", options.threads, "OpenMP threads (default: the case's `threads`)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--verbosity", verbosity, "quiet | normal | verbose | trace");
  cosim::add_coupling_options(app, endpoint);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : cosim::to_int(cosim::ExitCode::bad_input);
  }

  try {
    if (help_config) {
      std::cout << mpm::mpm_case_help();
      return 0;
    }
    if (options.config.empty() || options.output.empty())
      throw cosim::InputError("--config and --output are required (or --help-config)");
    options.verbosity = cosim::parse_verbosity(verbosity);
    // Coupled (an endpoint from `cosim run`): the coupling concept's
    // observers drive a cosim::Participant alongside the time loop.
    if (endpoint.is_standalone()) return mpm::run_case(options);
    return mpm::run_case(options, mpm::coupling::coupling_observers(endpoint));
  } catch (const cosim::Error& e) {
    std::cerr << "mpm_solver: error: " << e.what() << "\n";
    return cosim::to_int(e.code());
  } catch (const std::exception& e) {
    std::cerr << "mpm_solver: internal error: " << e.what() << "\n";
    return cosim::to_int(cosim::ExitCode::internal_error);
  }
}
