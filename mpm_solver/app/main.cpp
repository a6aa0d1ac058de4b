// mpm_solver: the explicit material point method, standalone or as a
// participant of a coupled job (`cosim run`); a `kind: depth_averaged_case`
// file runs the depth-averaged mass of van den Bout et al. (standalone, or
// coupled to a two-phase swe_fluid).
//
//   mpm_solver --config case.yaml --output run/ [--overwrite] [--threads N]
//   mpm_solver --validate --config case.yaml
//   mpm_solver --help-config

#include "cosim/solver_command_line.hpp"
#include "mpm/case/case_schema.hpp"
#include "mpm/case/load_case.hpp"
#include "mpm/coupling/coupling_observer.hpp"
#include "mpm/depth_averaged/depth_averaged_case.hpp"
#include "mpm/depth_averaged/depth_averaged_run.hpp"
#include "mpm/io/run_driver.hpp"

int main(int argc, char** argv) {
  return cosim::run_solver_program(
      {.name = "mpm_solver",
       .description = "mpm_solver: explicit material point method for soil and structures",
       .case_kind = "mpm_case",
       .help_config = [] { return mpm::mpm_case_help() + "\n" + mpm::depth_averaged_case_help(); },
       .run =
           [](const cosim::SolverCommandLine& line) {
             mpm::RunOptions options;
             options.config = line.config;
             options.output = line.output;
             options.threads = line.threads;
             options.verbosity = line.verbosity;
             options.reuse = line.reuse;
             if (mpm::is_depth_averaged_case(line.config))
               return mpm::run_depth_averaged_case(options, line.endpoint);
             if (line.endpoint.is_standalone() && mpm::started_on_several_ranks())
               return mpm::run_decomposed_case(options,
                                               mpm::coupling::standalone_observers(line.endpoint));
             // Coupled (an endpoint from `cosim run`), or standalone in
             // windows: the coupling concept's observers drive a
             // cosim::Participant alongside the time loop.
             if (line.endpoint.is_standalone())
               return mpm::run_case(options, mpm::coupling::standalone_observers(line.endpoint));
             if (line.endpoint.uri == "mpi://")
               return mpm::run_mpi_participant(options,
                                               mpm::coupling::coupling_observers(line.endpoint));
             return mpm::run_case(options, mpm::coupling::coupling_observers(line.endpoint));
           },
       .validate =
           [](const std::filesystem::path& config) {
             if (mpm::is_depth_averaged_case(config)) {
               mpm::DepthAveragedCase c = mpm::load_depth_averaged_case(config);
               return cosim::ValidatedCase{c.name, std::move(c.size), "depth_averaged_case"};
             }
             mpm::CaseDescription c = mpm::load_case(config);
             return cosim::ValidatedCase{c.name, std::move(c.size)};
           }},
      argc, argv);
}
