// openfoam_adapter: Debian's stock OpenFOAM v1912 (water and air, VOF) run
// through case files, restarted once per window.
//
//   openfoam_adapter --config case.yaml --output run/ [--overwrite]
//   openfoam_adapter --validate --config case.yaml
//   openfoam_adapter --help-config

#include "cosim/solver_command_line.hpp"
#include "openfoam/case/case_schema.hpp"
#include "openfoam/case/load_case.hpp"
#include "openfoam/io/run_case.hpp"

int main(int argc, char** argv) {
  return cosim::run_solver_program(
      {.name = "openfoam_adapter",
       .description = "openfoam_adapter: stock OpenFOAM (interFoam) driven through case files",
       .case_kind = "openfoam_case",
       .help_config = openfoam::openfoam_case_help,
       .run = openfoam::run_case,
       .validate =
           [](const std::filesystem::path& config) {
             openfoam::CaseDescription c = openfoam::load_case(config);
             return cosim::ValidatedCase{c.name, std::move(c.size)};
           }},
      argc, argv);
}
