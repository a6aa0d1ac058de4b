// ice_fluid: the native multi-material ICE solver (Tran et al., MPMICE),
// standalone or as a participant of a coupled job (`cosim run`).
//
//   ice_fluid --config case.yaml --output run/ [--threads N]
//   ice_fluid --help-config

#include "cosim/solver_command_line.hpp"
#include "ice/case/case_schema.hpp"
#include "ice/io/run_case.hpp"

int main(int argc, char** argv) {
  return cosim::run_solver_program(
      {.name = "ice_fluid",
       .description = "ice_fluid: multi-material compressible flow with implicit pressure (ICE)",
       .case_kind = "ice_case",
       .help_config = ice::ice_case_help,
       .run = ice::run_case},
      argc, argv);
}
