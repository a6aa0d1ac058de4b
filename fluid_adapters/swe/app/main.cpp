// swe_fluid: shallow-water finite volumes (1D non-uniform, 2D uniform),
// standalone or as a participant of a coupled job (`cosim run`).
//
//   swe_fluid --config case.yaml --output run/ [--overwrite] [--threads N]
//   swe_fluid --validate --config case.yaml
//   swe_fluid --help-config

#include "cosim/solver_command_line.hpp"
#include "swe/case/case_schema.hpp"
#include "swe/case/load_case.hpp"
#include "swe/io/run_case.hpp"

int main(int argc, char** argv) {
  return cosim::run_solver_program(
      {.name = "swe_fluid",
       .description = "swe_fluid: shallow-water finite volumes, well-balanced, wet/dry, moving bed",
       .case_kind = "swe_case",
       .help_config = swe::swe_case_help,
       .run =
           [](const cosim::SolverCommandLine& line) {
             swe::RunOptions options;
             options.config = line.config;
             options.output = line.output;
             options.threads = line.threads;
             options.verbosity = line.verbosity;
             options.reuse = line.reuse;
             return swe::run_case(options, line.endpoint);
           },
       .validate =
           [](const std::filesystem::path& config) {
             swe::CaseDescription c = swe::load_case(config);
             return cosim::ValidatedCase{c.name, std::move(c.size)};
           }},
      argc, argv);
}
