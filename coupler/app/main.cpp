// cosim: runs coupled jobs (`cosim run`), checks them (`cosim validate`),
// compares solver pairings on benchmark suites (`cosim bench`).

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "bench/analytic_solution.hpp"
#include "bench/bench.hpp"
#include "bench/suite.hpp"
#include "cosim/error.hpp"
#include "cosim/fields.hpp"
#include "cosim/runtime/stop_request.hpp"
#include "job/job.hpp"
#include "run_command.hpp"
#include "validate_command.hpp"

int main(int argc, char** argv) {
  cosim::runtime::install_stop_handlers();
  CLI::App app{"cosim: co-simulation of soil-water-structure interaction"};
  app.set_version_flag("--version", std::string("cosim ") + COSIM_VERSION);
  app.require_subcommand(0, 1);
  bool help_config_flag = false;
  app.add_flag("--help-config", help_config_flag, "list every key of a job file and exit");

  cosim::app::RunOptions run_options;
  auto* run_cmd = app.add_subcommand("run", "Run a coupled job");
  run_cmd->add_option("job", run_options.job_file, "the job's YAML file (kind: job)")->required();
  run_cmd->add_option("-o,--output", run_options.output, "run directory")->required();
  run_cmd->add_option("--verbosity", run_options.verbosity, "quiet | normal | verbose | trace");
  auto* print_mpi = run_cmd->add_flag("--print-mpi-command", run_options.print_mpi_command,
                                      "print the mpirun line of an MPI job and exit");
  run_cmd
      ->add_option("--slurm-script", run_options.slurm_script,
                   "write a Slurm batch script of an MPI job to FILE (and its srun multi-prog "
                   "configuration to FILE.multi-prog.conf) and exit, running nothing; submit it "
                   "with `sbatch FILE`")
      ->type_name("FILE")
      ->excludes(print_mpi);
  run_cmd->add_flag("--overwrite", run_options.overwrite,
                    "replace the earlier run a non-empty --output directory holds (with "
                    "--slurm-script: an existing script)");
  run_cmd
      ->add_option("--connect-timeout", run_options.connect_timeout_s,
                   "seconds to wait for every participant's hello (participants wait as long "
                   "for the coupler's welcome)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            double seconds = 0.0;
            try {
              seconds = std::stod(text);
            } catch (const std::exception&) {
              return "not a number: " + text;
            }
            if (!(seconds >= cosim::app::min_connect_timeout_s &&
                  seconds <= cosim::app::max_connect_timeout_s))
              return fmt::format("{} s is outside [{}, {}] s", text,
                                 cosim::app::min_connect_timeout_s,
                                 cosim::app::max_connect_timeout_s);
            return {};
          },
          "SECONDS in [0.1, 1e6]"));
  run_cmd->add_option("--job-id", run_options.job_id, "job id (set by the MPI launch)");
  run_cmd->add_option("--checkpoint-every", run_options.checkpoint_every,
                      "write a checkpoint of the coupled run every N windows (500) or every T "
                      "simulated seconds (0.5s) under <output>/checkpoints/");
  run_cmd
      ->add_option("--checkpoints-kept", run_options.checkpoints_kept,
                   "how many of the latest checkpoints to keep (default 2)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}));
  run_cmd->add_option("--restart", run_options.restart,
                      "continue from this checkpoint directory (<run>/checkpoints/window_<n>) "
                      "into a new --output directory");

  std::string validate_file;
  auto* validate_cmd = app.add_subcommand("validate", "Check a job file without running it");
  validate_cmd->add_option("job", validate_file, "the job's YAML file")->required();

  auto* help_config = app.add_subcommand("help-config", "List every key of a job file");
  auto* help_fields = app.add_subcommand(
      "help-fields", "List the fields solvers exchange: name, unit, mapping, window, meaning");

  cosim::bench::BenchRunOptions bench_options;
  std::string resolution = "coarse";
  bool bench_help_config = false;
  auto* bench_cmd = app.add_subcommand(
      "bench", "Run a suite of scenarios across solver pairings and write a comparison report");
  bench_cmd->add_option("suite", bench_options.bench.suite_file,
                        "the suite's YAML file (kind: bench_suite)");
  bench_cmd->add_option("-o,--output", bench_options.bench.output,
                        "report directory (results.csv, report.md, plots/, runs/)");
  bench_cmd
      ->add_option("--resolution", resolution,
                   "coarse (finishes in CI) or full (the papers' resolution)")
      ->check(CLI::IsMember({"coarse", "full"}));
  bench_cmd->add_option("--only", bench_options.bench.only, "run only these scenarios");
  bench_cmd->add_option("-j,--jobs", bench_options.bench.jobs, "runs at a time (default 1)")
      ->check(CLI::Range(1, 64));
  bench_cmd->add_option("--verbosity", bench_options.verbosity, "quiet | normal | verbose | trace");
  bench_cmd->add_flag("--dry-run", bench_options.dry_run,
                      "write each run's inputs and list the runs (kept or to run), run nothing");
  bool bench_resume = false, bench_overwrite = false;
  bench_cmd->add_flag("--resume", bench_resume,
                      "keep the finished runs of an earlier call with the same --output whose "
                      "inputs did not change; run the rest");
  bench_cmd
      ->add_flag("--overwrite", bench_overwrite,
                 "clear the report directory of an earlier call and start afresh")
      ->excludes("--resume");
  bench_cmd->add_flag("--help-config", bench_help_config,
                      "list every key of a suite file, the analytic solutions and every key of "
                      "a backend descriptor, and exit");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : cosim::to_int(cosim::ExitCode::bad_input);
  }

  try {
    if (*help_config || help_config_flag) {
      std::cout << cosim::job::job_help();
      return 0;
    }
    if (*help_fields) {
      std::cout << cosim::fields::help();
      return 0;
    }
    if (*validate_cmd) return cosim::app::validate_job(validate_file);
    if (*run_cmd) return cosim::app::run_job(run_options);
    if (*bench_cmd) {
      if (bench_help_config) {
        std::cout << cosim::bench::suite_schema().help("Bench suite file (kind: bench_suite)")
                  << "\n"
                  << cosim::bench::analytic_solutions_help() << "\n"
                  << cosim::bench::backend_descriptor_schema().help(
                         "Backend descriptor (kind: bench_backend; "
                         "share/cosim/backends/<name>.yaml)");
        return 0;
      }
      if (bench_options.bench.suite_file.empty() || bench_options.bench.output.empty())
        throw cosim::InputError("cosim bench: give the suite file and --output <dir>");
      bench_options.bench.resolution =
          resolution == "full" ? cosim::bench::Resolution::full : cosim::bench::Resolution::coarse;
      bench_options.reuse = bench_resume      ? cosim::OutputReuse::resume
                            : bench_overwrite ? cosim::OutputReuse::overwrite
                                              : cosim::OutputReuse::refuse;
      bench_options.terminal = ::isatty(STDERR_FILENO) != 0;
      bench_options.interrupted = &cosim::runtime::stop_flag();
      return cosim::bench::run_bench(bench_options);
    }
    std::cerr << app.help();
    return cosim::to_int(cosim::ExitCode::bad_input);
  } catch (const cosim::Error& e) {
    std::cerr << "cosim: error: " << e.what() << "\n";
    return cosim::to_int(e.code());
  } catch (const std::exception& e) {
    std::cerr << "cosim: internal error: " << e.what() << "\n";
    return 1;
  }
}
