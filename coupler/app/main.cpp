// cosim: runs coupled jobs (`cosim run`), checks them (`cosim validate`),
// compares solver pairings on benchmark suites (`cosim bench`).

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <random>

#include "cosim/bench/analytic_solution.hpp"
#include "cosim/bench/bench.hpp"
#include "cosim/bench/suite.hpp"
#include "cosim/com/mpi_transport.hpp"
#include "cosim/com/zmq_transport.hpp"
#include "cosim/cplscheme/coupler.hpp"
#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/job/job.hpp"
#include "cosim/runtime/mpi_launch.hpp"
#include "cosim/runtime/supervisor.hpp"

namespace {

std::atomic<bool> interrupted{false};

void on_signal(int) {
  interrupted = true;
}

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGHUP, &action, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
}

std::string new_job_id(const std::string& name) {
  std::random_device device;
  return fmt::format("{}-{:08x}", name, device());
}

struct RunOptions {
  std::string job_file;
  std::string output;
  std::string job_id;
  std::string verbosity = "normal";
  bool print_mpi_command = false;
  double connect_timeout_s = 120.0;
};

// The participants run as children of this process, talking over ZeroMQ.
void run_with_zmq(const cosim::job::Job& job, const RunOptions& o, cosim::RunSummary& summary) {
  namespace fs = std::filesystem;
  cosim::com::ZmqHubOptions hub_options;
  hub_options.scheme =
      job.zmq.scheme == "tcp" ? cosim::com::ZmqScheme::tcp : cosim::com::ZmqScheme::ipc;
  hub_options.tcp_host = job.zmq.host;
  hub_options.allow_non_loopback = job.zmq.allow_non_loopback;
  cosim::com::ZmqHub hub(hub_options);
  spdlog::info("job '{}' (id {}, config hash {}): {}", job.name, o.job_id, job.config_hash,
               hub.describe());

  // Every executable is found before any process starts.
  std::vector<fs::path> executables;
  for (const auto& p : job.participants)
    executables.push_back(cosim::runtime::resolve_executable(p.executable, job.file.parent_path()));

  cosim::runtime::Supervisor supervisor;
  const fs::path output = fs::absolute(o.output);
  for (std::size_t i = 0; i < job.participants.size(); ++i) {
    const auto& p = job.participants[i];
    cosim::runtime::ChildSpec child;
    child.name = p.name;
    child.executable = executables[i];
    child.args =
        cosim::runtime::participant_arguments(p, output, hub.endpoint(), o.job_id, job.config_hash);
    cosim::create_output_directory(output / p.name);
    child.log_file = output / p.name / "console.log";
    const pid_t pid = supervisor.start(child);
    spdlog::info("started participant '{}' (pid {}): {} {}", p.name, pid, child.executable.string(),
                 cosim::runtime::shell_join(child.args));
  }

  cosim::cplscheme::CouplerOptions options;
  options.output_dir = output;
  options.job_id = o.job_id;
  options.connect_timeout_s = o.connect_timeout_s;
  options.progress_on_terminal = ::isatty(STDERR_FILENO) != 0;
  options.interrupted = &interrupted;
  cosim::cplscheme::Coupler coupler(job, hub, &supervisor, summary, options);
  try {
    coupler.run();
  } catch (...) {
    supervisor.stop_all(std::chrono::milliseconds(3000));
    throw;
  }
  // After `finish`, each participant writes its output and exits by itself.
  for (const auto& e : supervisor.wait_all(
           std::chrono::milliseconds(static_cast<long>(job.window_timeout_s * 1000.0)))) {
    if (!e.success())
      throw cosim::Error(cosim::ExitCode::participant_failed,
                         fmt::format("participant '{}' {} after the run", e.name, e.describe()));
  }
  if (supervisor.running() > 0) {
    supervisor.stop_all(std::chrono::milliseconds(2000));
    throw cosim::Error(cosim::ExitCode::participant_failed,
                       "participants did not exit after the end of the run");
  }
}

// Under mpirun: this process is world rank 0, the participants are the other
// applications of the MPMD launch.
void run_under_mpirun(const cosim::job::Job& job, const RunOptions& o, cosim::RunSummary& summary) {
  cosim::com::MpiHub hub;
  const int expected = 1 + static_cast<int>(job.participants.size());
  if (hub.world_size() != expected)
    throw cosim::InputError(
        fmt::format("the mpirun line has {} processes; job '{}' needs {} (the "
                    "coupler and one per participant): use `cosim run {} "
                    "--print-mpi-command`",
                    hub.world_size(), job.name, expected, o.job_file));
  cosim::cplscheme::CouplerOptions options;
  options.output_dir = std::filesystem::absolute(o.output);
  options.job_id = o.job_id;
  options.connect_timeout_s = o.connect_timeout_s;
  options.interrupted = &interrupted;
  cosim::cplscheme::Coupler coupler(job, hub, nullptr, summary, options);
  coupler.run();
}

// Not under mpirun: start mpirun with the job's MPMD line and supervise it.
int launch_mpirun(const cosim::job::Job& job, const RunOptions& o) {
  const auto cmd = cosim::runtime::mpi_command(job, o.job_file, o.output, o.job_id);
  cosim::create_output_directory(o.output);
  cosim::runtime::Supervisor supervisor;
  cosim::runtime::ChildSpec child;
  child.name = "mpirun";
  child.executable = cosim::runtime::resolve_executable("mpirun", ".");
  child.args.assign(cmd.begin() + 1, cmd.end());
  child.log_file = std::filesystem::path(o.output) / "mpirun.log";
  std::cerr << "cosim: launching " << cosim::runtime::shell_join(cmd) << "\n";
  supervisor.start(child);
  for (;;) {
    if (interrupted) {
      supervisor.stop_all(std::chrono::milliseconds(3000));
      return cosim::to_int(cosim::ExitCode::participant_failed);
    }
    auto exits = supervisor.wait_all(std::chrono::milliseconds(200));
    if (exits.empty()) continue;
    const auto& e = exits.front();
    if (e.success()) return 0;
    std::cerr << "cosim: mpirun " << e.describe() << "; see " << child.log_file.string() << "\n";
    const int s = e.exit_status;
    return (s == 2 || s == 3 || s == 4) ? s : cosim::to_int(cosim::ExitCode::participant_failed);
  }
}

int run(const RunOptions& o) {
  namespace fs = std::filesystem;
  const cosim::job::Job job = cosim::job::load_job(o.job_file);
  RunOptions opts = o;
  if (opts.job_id.empty()) opts.job_id = new_job_id(job.name);
  if (job.transport == cosim::job::TransportKind::mpi && !cosim::com::launched_by_mpirun()) {
    if (o.print_mpi_command) {
      std::cout << cosim::runtime::shell_join(
                       cosim::runtime::mpi_command(job, o.job_file, o.output, opts.job_id))
                << "\n";
      return 0;
    }
    return launch_mpirun(job, opts);
  }
  if (o.print_mpi_command)
    throw cosim::InputError(
        fmt::format("{}: job '{}' uses transport '{}'; --print-mpi-command "
                    "needs 'transport: mpi'",
                    o.job_file, job.name, "zmq"));

  cosim::create_output_directory(o.output);
  cosim::init_logging(o.output, "cosim", cosim::parse_verbosity(o.verbosity));
  cosim::RunSummary summary(o.output, "cosim run");
  summary.set_config(fs::absolute(o.job_file), std::stoull(job.config_hash, nullptr, 16));
  summary.set_section(
      "job", {{"name", job.name},
              {"id", opts.job_id},
              {"transport", job.transport == cosim::job::TransportKind::mpi ? "mpi" : "zmq"},
              {"window_s", job.window},
              {"start_time_s", job.start_time},
              {"end_time_s", job.end_time}});
  summary.write();
  const int code = cosim::run_and_finish(summary, [&] {
    if (job.transport == cosim::job::TransportKind::mpi)
      run_under_mpirun(job, opts, summary);
    else
      run_with_zmq(job, opts, summary);
  });
  if (code != 0) return code;
  spdlog::info("job '{}' completed: {} windows, wall time {:.3f} s; outputs in {}", job.name,
               job.windows(), summary.phases().total_seconds(), fs::absolute(o.output).string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  install_signal_handlers();
  CLI::App app{"cosim: co-simulation of soil-water-structure interaction"};
  app.set_version_flag("--version", std::string("cosim ") + COSIM_VERSION);
  app.require_subcommand(0, 1);
  bool help_config_flag = false;
  app.add_flag("--help-config", help_config_flag, "list every key of a job file and exit");

  RunOptions run_options;
  auto* run_cmd = app.add_subcommand("run", "Run a coupled job");
  run_cmd->add_option("job", run_options.job_file, "the job's YAML file (kind: job)")->required();
  run_cmd->add_option("-o,--output", run_options.output, "run directory")->required();
  run_cmd->add_option("--verbosity", run_options.verbosity, "quiet | normal | verbose | trace");
  run_cmd->add_flag("--print-mpi-command", run_options.print_mpi_command,
                    "print the mpirun line of an MPI job and exit");
  run_cmd
      ->add_option("--connect-timeout", run_options.connect_timeout_s,
                   "seconds to wait for every participant's hello")
      ->check(CLI::PositiveNumber);
  run_cmd->add_option("--job-id", run_options.job_id, "job id (set by the MPI launch)");

  std::string validate_file;
  auto* validate_cmd = app.add_subcommand("validate", "Check a job file without running it");
  validate_cmd->add_option("job", validate_file, "the job's YAML file")->required();

  auto* help_config = app.add_subcommand("help-config", "List every key of a job file");

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
  bench_cmd->add_flag("--overwrite", bench_overwrite,
                      "clear the report directory of an earlier call and start afresh")
      ->excludes("--resume");
  bench_cmd->add_flag("--help-config", bench_help_config,
                      "list every key of a suite file and the analytic solutions, and exit");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : cosim::to_int(cosim::ExitCode::bad_input);
  }

  try {
    if (*help_config || help_config_flag) {
      std::cout << cosim::job::job_schema().help("Job file (kind: job)");
      return 0;
    }
    if (*validate_cmd) {
      const auto job = cosim::job::load_job(validate_file);
      std::cout << fmt::format(
          "{}: job '{}' is valid: {} participants, {} exchanges, {} windows "
          "of {} s, config hash {}\n",
          validate_file, job.name, job.participants.size(), job.exchanges.size(), job.windows(),
          job.window, job.config_hash);
      return 0;
    }
    if (*run_cmd) return run(run_options);
    if (*bench_cmd) {
      if (bench_help_config) {
        std::cout << cosim::bench::suite_schema().help("Bench suite file (kind: bench_suite)")
                  << "\n"
                  << cosim::bench::analytic_solutions_help();
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
      bench_options.interrupted = &interrupted;
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
