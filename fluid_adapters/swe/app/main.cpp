// swe_fluid: shallow-water finite volumes (1D non-uniform, 2D uniform),
// standalone or as a participant of a coupled job (`cosim run`).
//
//   swe_fluid --config case.yaml --output run/ [--threads N]
//   swe_fluid --help-config

#include <CLI/CLI.hpp>
#include <iostream>

#include "cosim/error.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/participant.hpp"
#include "swe/case/case_schema.hpp"
#include "swe/io/run_case.hpp"

int main(int argc, char** argv) {
  CLI::App app{"swe_fluid: shallow-water finite volumes, well-balanced, wet/dry, moving bed"};
  bool help_config = false;
  std::string verbosity = "normal";
  swe::RunOptions options;
  cosim::CouplingEndpoint endpoint;
  app.add_flag("--help-config", help_config, "list every key of a case file (kind: swe_case) and exit");
  app.add_option("-c,--config", options.config, "the case's YAML file (kind: swe_case)");
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
      std::cout << swe::swe_case_help();
      return 0;
    }
    if (options.config.empty() || options.output.empty())
      throw cosim::InputError("--config and --output are required (or --help-config)");
    options.verbosity = cosim::parse_verbosity(verbosity);
    return swe::run_case(options, endpoint);
  } catch (const cosim::Error& e) {
    std::cerr << "swe_fluid: error: " << e.what() << "\n";
    return cosim::to_int(e.code());
  } catch (const std::exception& e) {
    std::cerr << "swe_fluid: internal error: " << e.what() << "\n";
    return cosim::to_int(cosim::ExitCode::internal_error);
  }
}
