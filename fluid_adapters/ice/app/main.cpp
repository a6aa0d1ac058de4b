// ice_fluid: the native multi-material ICE solver (Tran et al., MPMICE),
// standalone or as a participant of a coupled job (`cosim run`).
//
//   ice_fluid --config case.yaml --output run/ [--overwrite] [--threads N]
//   ice_fluid --validate --config case.yaml
//   ice_fluid --help-config

#include "cosim/solver_command_line.hpp"
#include "ice/case/case_schema.hpp"
#include "ice/case/load_case.hpp"
#include "ice/io/run_case.hpp"

int main(int argc, char** argv) {
  return cosim::run_solver_program(
      {.name = "ice_fluid",
       .description = "ice_fluid: multi-material compressible flow with implicit pressure (ICE)",
       .case_kind = "ice_case",
       .help_config = ice::ice_case_help,
       .run = ice::run_case,
       .validate =
           [](const std::filesystem::path& config) {
             ice::CaseDescription c = ice::load_case(config);
             return cosim::ValidatedCase{c.name, std::move(c.size)};
           }},
      argc, argv);
}
