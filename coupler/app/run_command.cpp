#include "run_command.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <sys/prctl.h>
#include <sys/random.h>
#include <unistd.h>

#include <array>
#include <csignal>
#include <iostream>
#include <random>
#include <string_view>

#include "bench/backend_catalog.hpp"
#include "checkpoint/manifest.hpp"
#include "com/mpi_transport.hpp"
#include "com/zmq_transport.hpp"
#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/runtime/mpi_launch_environment.hpp"
#include "cosim/runtime/stop_request.hpp"
#include "cosim/runtime/supervisor.hpp"
#include "cplscheme/coupler.hpp"
#include "job/job.hpp"
#include "m2n/partitioned_hub.hpp"
#include "mpi_launcher.hpp"
#include "runtime/mpi_launch.hpp"
#include "runtime/slurm_script.hpp"

namespace cosim::app {

namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

// How long participants told to abort may take to finish their records
// before they are asked (SIGTERM), then made (SIGKILL), to stop.
constexpr milliseconds abort_grace{3000};
constexpr milliseconds stop_grace{3000};

std::string new_job_id(const std::string& name) {
  std::random_device device;
  return fmt::format("{}-{:08x}", name, device());
}

// 128 random bits from the kernel, as hex.
std::string new_run_token() {
  std::array<unsigned char, 16> bytes{};
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::getrandom(bytes.data() + got, bytes.size() - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error(ExitCode::internal_error, "getrandom failed: no run token");
    got += static_cast<std::size_t>(n);
  }
  std::string hex;
  for (unsigned char b : bytes) hex += fmt::format("{:02x}", b);
  return hex;
}

// The peers of the MpiHub, one per world rank after the coupler's: a
// participant on N > 1 ranks as `name[0]` ... `name[N-1]`, on one rank as
// `name`.
std::vector<std::string> participant_names(const job::Job& job) {
  return runtime::rank_peer_names(job);
}

// Ends every participant still running after a failed or interrupted run:
// those the coupler told to abort get a moment to finish their records and
// exit by themselves, the rest are stopped; a participant that died without
// finishing its summary.json (a signal) has it finished by the coupler.
void end_participants(runtime::Supervisor& supervisor, const fs::path& output) {
  const auto deadline = std::chrono::steady_clock::now() + abort_grace;
  while (supervisor.running() > 0 && !supervisor.all_running_stopped() &&
         std::chrono::steady_clock::now() < deadline)
    supervisor.wait_all(milliseconds(50));
  supervisor.stop_all(stop_grace);
  for (const runtime::ChildExit& e : supervisor.exited())
    if (!e.success())
      record_failure_in_summary(
          output / e.name / "summary.json", e.coupled_exit_code(),
          fmt::format("participant '{}' {} (recorded by cosim)", e.name, e.describe()));
}

// --checkpoint-every and --restart, checked before any process starts: a
// checkpoint of another job or version, or one with a file missing or
// changed, is refused (exit 2) saying which.
void check_checkpoint_options(const job::Job& job, const RunOptions& o) {
  if (o.checkpoint_every.empty() && o.restart.empty()) return;
  if (!o.checkpoint_every.empty()) (void)checkpoint::Schedule::parse(o.checkpoint_every);
  const char* option = o.restart.empty() ? "--checkpoint-every" : "--restart";
  if (job.coupling.is_serial())
    throw InputError(
        fmt::format("{}: job '{}' couples serially (coupling.scheme: serial-...), "
                    "whose checkpoints are not built yet; use a parallel scheme",
                    option, job.name));
  if (o.restart.empty()) return;
  const checkpoint::Manifest m = checkpoint::read_manifest(o.restart);
  checkpoint::check_same_job(m, o.restart, job.name, job.config_hash,
                             job.config_hash_without_ranks);
  if (o.overwrite && is_inside(o.restart, o.output))
    throw InputError(
        fmt::format("--restart {} lies inside --output {}, which --overwrite would "
                    "delete; restart into another directory",
                    o.restart, o.output));
}

void set_checkpoint_options(const RunOptions& o, cplscheme::CouplerOptions& options) {
  if (!o.checkpoint_every.empty())
    options.checkpoint_every = checkpoint::Schedule::parse(o.checkpoint_every);
  options.checkpoints_kept = o.checkpoints_kept;
  if (o.restart.empty()) return;
  options.restart = fs::absolute(o.restart);
  options.restart_window = checkpoint::read_manifest(o.restart).window;
}

// The participants run as children of this process, talking over ZeroMQ.
void run_with_zmq(const job::Job& job, const RunOptions& o, RunSummary& summary) {
  com::ZmqHubOptions hub_options;
  hub_options.scheme = job.zmq.scheme == "tcp" ? com::ZmqScheme::tcp : com::ZmqScheme::ipc;
  hub_options.tcp_host = job.zmq.host;
  hub_options.allow_non_loopback = job.zmq.allow_non_loopback;
  com::ZmqHub hub(hub_options);
  spdlog::info("job '{}' (id {}, config hash {}): {}", job.name, o.job_id, job.config_hash,
               hub.describe());

  // Every executable is found before any process starts.
  std::vector<fs::path> executables;
  for (const auto& p : job.participants)
    executables.push_back(runtime::resolve_executable(p.executable, job.file.parent_path()));

  runtime::Supervisor supervisor;
  const fs::path output = fs::absolute(o.output);
  cplscheme::CouplerOptions options;
  for (std::size_t i = 0; i < job.participants.size(); ++i) {
    const auto& p = job.participants[i];
    runtime::ChildSpec child;
    child.name = p.name;
    child.executable = executables[i];
    child.args = runtime::participant_arguments(p, output, hub.endpoint(), o.job_id,
                                                job.config_hash, o.connect_timeout_s);
    if (!o.restart.empty())
      child.args.insert(child.args.end(),
                        {"--cosim-restart", (fs::absolute(o.restart) / p.name).string()});
    options.tokens[p.name] = new_run_token();
    child.environment = {{"COSIM_TOKEN", options.tokens[p.name]}};
    create_output_directory(output / p.name);
    child.log_file = output / p.name / "console.log";
    try {
      const pid_t pid = supervisor.start(child);
      spdlog::info("started participant '{}' (pid {}): {} {}", p.name, pid,
                   child.executable.string(), runtime::shell_join(child.args));
    } catch (...) {
      end_participants(supervisor, output);
      throw;
    }
  }

  options.output_dir = output;
  options.job_id = o.job_id;
  options.connect_timeout_s = o.connect_timeout_s;
  options.progress_on_terminal = ::isatty(STDERR_FILENO) != 0;
  options.interrupted = &runtime::stop_flag();
  set_checkpoint_options(o, options);
  cplscheme::Coupler coupler(job, hub, &supervisor, summary, options);
  try {
    coupler.run();
  } catch (...) {
    end_participants(supervisor, output);
    throw;
  }
  // After `finish`, each participant writes its output and exits by itself;
  // so it does after its part of a checkpoint the run stops at.
  const auto window_timeout = milliseconds(static_cast<long>(job.window_timeout_s * 1000.0));
  const bool stopped = coupler.stopped_at_checkpoint();
  const auto exits = supervisor.wait_all(window_timeout, stopped ? nullptr : &runtime::stop_flag());
  if (runtime::stop_requested() && !stopped) {
    end_participants(supervisor, output);
    throw Error(
        ExitCode::participant_failed,
        fmt::format("{} after the last window; participants stopped", runtime::describe_stop()));
  }
  for (const auto& e : exits) {
    if (e.success()) continue;
    end_participants(supervisor, output);
    throw Error(e.coupled_exit_code(),
                fmt::format("participant '{}' {} after the run", e.name, e.describe()));
  }
  if (supervisor.running() > 0) {
    const std::string names = supervisor.running_names();
    end_participants(supervisor, output);
    throw Error(ExitCode::participant_failed,
                fmt::format("participant(s) {} did not exit within window_timeout ({} s) after "
                            "the end of the run",
                            names, job.window_timeout_s));
  }
  if (stopped)
    throw Error(ExitCode::stopped_at_checkpoint,
                fmt::format("{}: stopped at the checkpoint of window {} ({}); `cosim run {} "
                            "--restart <that checkpoint> --output <a new directory>` continues",
                            runtime::describe_stop(), summary.windows(),
                            (output / "checkpoints").string(), o.job_file));
}

// Under mpirun: this process is world rank 0, the participants are the other
// applications of the MPMD launch. A failed run ends the whole MPI job
// (MPI_Abort) once its record is written: the other ranks may never reach
// MPI_Finalize (a stopped participant), and waiting there would hang.
int run_under_mpirun(const job::Job& job, const RunOptions& o, RunSummary& summary) {
  com::MpiHub hub(participant_names(job));
  const int code = run_and_finish(summary, [&] {
    const int expected = runtime::mpi_world_size(job);
    if (hub.world_size() != expected)
      throw InputError(
          fmt::format("the MPI job has {} processes; job '{}' needs {} (1 for the "
                      "coupler + the sum of the participants' ranks): use `cosim run {} "
                      "--print-mpi-command`",
                      hub.world_size(), job.name, expected, o.job_file));
    cplscheme::CouplerOptions options;
    options.output_dir = fs::absolute(o.output);
    options.job_id = o.job_id;
    options.connect_timeout_s = o.connect_timeout_s;
    options.interrupted = &runtime::stop_flag();
    set_checkpoint_options(o, options);
    m2n::PartitionedHub parts(hub, runtime::part_peer_name);
    cplscheme::Coupler coupler(job, parts, nullptr, summary, options);
    coupler.run();
    if (coupler.stopped_at_checkpoint())
      throw Error(ExitCode::stopped_at_checkpoint,
                  fmt::format("{}: stopped at the checkpoint of window {} ({}); `cosim run {} "
                              "--restart <that checkpoint> --output <a new directory>` continues",
                              runtime::describe_stop(), summary.windows(),
                              (options.output_dir / "checkpoints").string(), o.job_file));
  });
  // A run stopped at a checkpoint ends as a finished one: every participant
  // wrote its part and ends by itself.
  if (code != 0 && code != to_int(ExitCode::stopped_at_checkpoint)) {
    spdlog::default_logger()->flush();
    hub.abort_job(code);
  }
  return code;
}

// The run's record, "running" until it ends.
RunSummary begin_summary(const job::Job& job, const RunOptions& o) {
  RunSummary summary(o.output, "cosim run");
  summary.set_config(fs::absolute(o.job_file), std::stoull(job.config_hash, nullptr, 16));
  summary.set_section("job",
                      {{"name", job.name},
                       {"id", o.job_id},
                       {"transport", job.transport == job::TransportKind::mpi ? "mpi" : "zmq"},
                       {"window_s", job.window},
                       {"start_time_s", job.start_time},
                       {"end_time_s", job.end_time}});
  summary.write();
  return summary;
}

}  // namespace

int run_job(const RunOptions& o) {
  const job::Job job = job::load_job(o.job_file, bench::programs_starting_their_processes());
  RunOptions opts = o;
  if (opts.job_id.empty()) opts.job_id = new_job_id(job.name);
  const bool under_mpirun = runtime::launched_as_mpi_rank();
  if (job.transport == job::TransportKind::mpi && !under_mpirun) {
    if (o.print_mpi_command) {
      check_checkpoint_options(job, opts);
      std::cout << runtime::shell_join(runtime::mpi_command(job, o.job_file, o.output, opts.job_id,
                                                            o.connect_timeout_s,
                                                            checkpoint_arguments(opts)))
                << "\n";
      return 0;
    }
    if (!o.slurm_script.empty()) {
      check_checkpoint_options(job, opts);
      runtime::write_slurm_script(job, o.job_file, o.output, opts.job_id, o.connect_timeout_s,
                                  o.slurm_script, o.overwrite, checkpoint_arguments(opts));
      std::cout << "cosim: wrote " << o.slurm_script << " and "
                << runtime::multi_prog_path(o.slurm_script).string() << " (job '" << job.name
                << "', id " << opts.job_id << ", " << runtime::mpi_world_size(job)
                << " tasks); submit it with `sbatch " << o.slurm_script << "`\n";
      return 0;
    }
    check_checkpoint_options(job, opts);
    runtime::check_ranks_fit(job, runtime::available_cores());
    prepare_output_directory(o.output, o.overwrite ? OutputReuse::overwrite : OutputReuse::refuse);
    // The coupler rank rewrites it once it runs; until then (and if it
    // never does) the record is this process's.
    begin_summary(job, opts);
    return launch_mpirun(job, opts);
  }
  check_checkpoint_options(job, opts);
  for (const auto& [given, option] : {std::pair{o.print_mpi_command, "--print-mpi-command"},
                                      std::pair{!o.slurm_script.empty(), "--slurm-script"}})
    if (given)
      throw InputError(fmt::format("{}: job '{}' uses transport '{}'; {} needs 'transport: mpi'",
                                   o.job_file, job.name, "zmq", option));

  // Under mpirun the launching cosim has prepared the directory (and writes
  // mpirun.log into it); this rank dies with mpirun.
  if (under_mpirun) ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (!under_mpirun)
    prepare_output_directory(o.output, o.overwrite ? OutputReuse::overwrite : OutputReuse::refuse);
  init_logging(o.output, "cosim", parse_verbosity(o.verbosity));
  RunSummary summary = begin_summary(job, opts);
  const int code = job.transport == job::TransportKind::mpi
                       ? run_under_mpirun(job, opts, summary)
                       : run_and_finish(summary, [&] { run_with_zmq(job, opts, summary); });
  if (code != 0) return code;
  spdlog::info("job '{}' completed: {} windows, wall time {:.3f} s; outputs in {}", job.name,
               job.windows(), summary.phases().total_seconds(), fs::absolute(o.output).string());
  return 0;
}

}  // namespace cosim::app
