// openfoam_adapter: Debian's stock OpenFOAM v1912 (water and air, VOF) run
// through case files, restarted once per window.
//
//   openfoam_adapter --config case.yaml --output run/
//   openfoam_adapter --help-config

#include "cosim/solver_command_line.hpp"
#include "openfoam/case/case_schema.hpp"
#include "openfoam/io/run_case.hpp"

int main(int argc, char** argv) {
  return cosim::run_solver_program(
      {.name = "openfoam_adapter",
       .description = "openfoam_adapter: stock OpenFOAM (interFoam) driven through case files",
       .case_kind = "openfoam_case",
       .help_config = openfoam::openfoam_case_help,
       .run = openfoam::run_case},
      argc, argv);
}
