#include "mpi_launcher.hpp"

#include <fmt/format.h>
#include <signal.h>

#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string_view>
#include <thread>

#include "cosim/error.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/io/tail_lines.hpp"
#include "cosim/runtime/stop_request.hpp"
#include "cosim/runtime/supervisor.hpp"
#include "runtime/mpi_launch.hpp"

namespace cosim::app {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

constexpr milliseconds stop_grace{3000};
// mpirun's own start-up on top of the connect timeout.
constexpr milliseconds launch_slack{5000};

// What the coupler rank has recorded of the run so far.
struct RecordedStatus {
  bool finished = false;
  int exit_code = 0;
  std::string message;
  bool coupling = false;  // past the admission (window 0 exchanged)
};

std::optional<RecordedStatus> read_status(const fs::path& summary) {
  std::ifstream in(summary);
  if (!in) return std::nullopt;
  try {
    const auto j = nlohmann::json::parse(in);
    RecordedStatus s;
    s.finished = j.at("status").at("state") == "finished";
    if (s.finished) s.exit_code = j["status"]["exit_code"].get<int>();
    s.message = j["status"].value("message", "");
    s.coupling = !j.at("progress").at("simulated_time_s").is_null();
    return s;
  } catch (const std::exception&) {
    return std::nullopt;  // being replaced at this moment
  }
}

struct RankProcess {
  pid_t pid = 0;
  char state = 0;    // of /proc/<pid>/stat: 'T' when stopped
  std::string role;  // "participant 'soil'" or "the coupler"
};

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The processes below `root` (mpirun's ranks and anything they started),
// from /proc, with what each is in the job (its --cosim-name, or the
// coupler's `cosim run`).
std::vector<RankProcess> processes_below(pid_t root) {
  std::map<pid_t, std::pair<pid_t, char>> parent_and_state;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string stat = read_file(entry.path() / "stat");
    const auto end = stat.rfind(')');
    if (end == std::string::npos || end + 4 >= stat.size()) continue;
    std::istringstream fields(stat.substr(end + 2));
    char state = 0;
    pid_t parent = 0;
    fields >> state >> parent;
    parent_and_state[static_cast<pid_t>(std::stol(name))] = {parent, state};
  }
  std::vector<RankProcess> below;
  std::vector<pid_t> frontier{root};
  while (!frontier.empty()) {
    const pid_t p = frontier.back();
    frontier.pop_back();
    for (const auto& [pid, ps] : parent_and_state) {
      if (ps.first != p) continue;
      frontier.push_back(pid);
      RankProcess r{pid, ps.second, {}};
      std::string cmdline = read_file(fmt::format("/proc/{}/cmdline", pid));
      std::vector<std::string> args;
      for (std::size_t at = 0; at < cmdline.size();) {
        const auto zero = cmdline.find('\0', at);
        args.push_back(cmdline.substr(at, zero - at));
        at = zero == std::string::npos ? cmdline.size() : zero + 1;
      }
      for (std::size_t i = 0; i + 1 < args.size(); ++i)
        if (args[i] == "--cosim-name") r.role = fmt::format("participant '{}'", args[i + 1]);
      if (r.role.empty() && args.size() > 1 && args[1] == "run") r.role = "the coupler";
      below.push_back(r);
    }
  }
  return below;
}

// Stops mpirun (which forwards the signal to its ranks), then makes sure of
// every process below it: ranks stuck in MPI_Init or MPI_Finalize, or
// stopped, may not answer mpirun.
void stop_job(runtime::Supervisor& supervisor, pid_t mpirun) {
  const std::vector<RankProcess> below = processes_below(mpirun);
  supervisor.stop_all(stop_grace);
  for (const RankProcess& r : below) ::kill(r.pid, SIGKILL);
}

// The coupler rank's process, when it runs.
std::optional<pid_t> coupler_rank(pid_t mpirun) {
  for (const RankProcess& r : processes_below(mpirun))
    if (r.role == "the coupler") return r.pid;
  return std::nullopt;
}

// Who holds the job: the ranks that are stopped, by role.
std::string stopped_ranks(const std::vector<RankProcess>& below) {
  std::string out;
  for (const RankProcess& r : below)
    if (r.state == 'T' && !r.role.empty())
      out += fmt::format("{}{} (pid {}) is stopped", out.empty() ? "" : "; ", r.role, r.pid);
  return out;
}

// The participant Open MPI names in its report of a rank that died ("process
// rank 2 with PID 4242 on node x exited on signal 9 (Killed)."): the launch
// line puts the participants' ranks after the coupler's, in job order
// (runtime::rank_peer_names: `soil[1]` for the second rank of `soil`).
std::string dead_rank_report(const job::Job& job, const fs::path& mpirun_log) {
  constexpr std::string_view rank_marker = "process rank ";
  constexpr std::string_view pid_marker = " with PID ";
  for (const auto& line : tail_lines(mpirun_log, 200)) {
    const auto at = line.find(rank_marker);
    if (at == std::string::npos) continue;
    int rank = 0;
    try {
      rank = std::stoi(line.substr(at + rank_marker.size()));
    } catch (const std::exception&) {
      continue;
    }
    std::string pid = "?";
    if (const auto p = line.find(pid_marker); p != std::string::npos) {
      const auto start = p + pid_marker.size();
      pid = line.substr(start, line.find(' ', start) - start);
    }
    std::string what = " died";
    if (const auto e = line.find("exited"); e != std::string::npos) what = " " + line.substr(e);
    while (!what.empty() && (what.back() == '.' || what.back() == ' ')) what.pop_back();
    if (rank == 0) return fmt::format("the coupler (world rank 0, pid {}){}", pid, what);
    const auto peers = runtime::rank_peer_names(job);
    if (rank > 0 && rank <= static_cast<int>(peers.size()))
      return fmt::format("participant '{}' (world rank {}, pid {}){}",
                         peers[static_cast<std::size_t>(rank - 1)], rank, pid, what);
  }
  return {};
}

// A participant whose ranks failed before it said hello to the coupler
// stops the MPI job itself (MPI_Abort in runtime::MpiSession::finish),
// having recorded why in its summary.json: the first participant whose
// summary ends with a non-zero code of its own (not the coupler's refusal or
// abort, "the coupler ..."), as "participant 'soil': <message>".
std::optional<std::pair<int, std::string>> failed_participant(const job::Job& job,
                                                              const fs::path& output) {
  for (const auto& p : job.participants) {
    const auto status = read_status(output / p.name / "summary.json");
    if (status && status->finished && status->exit_code != 0 &&
        status->message.rfind("the coupler ", 0) != 0)
      return std::pair{status->exit_code,
                       fmt::format("participant '{}' failed before the coupling began (exit "
                                   "code {}): {}",
                                   p.name, status->exit_code, status->message)};
  }
  return std::nullopt;
}

}  // namespace

runtime::CheckpointArguments checkpoint_arguments(const RunOptions& o) {
  return {o.checkpoint_every, o.checkpoints_kept, o.restart};
}

int launch_mpirun(const job::Job& job, const RunOptions& o) {
  const auto cmd = runtime::mpi_command(job, o.job_file, o.output, o.job_id, o.connect_timeout_s,
                                        checkpoint_arguments(o));
  const fs::path output = fs::absolute(o.output);
  runtime::Supervisor supervisor;
  runtime::ChildSpec child;
  child.name = "mpirun";
  child.executable = runtime::resolve_executable("mpirun", ".");
  child.args.assign(cmd.begin() + 1, cmd.end());
  child.log_file = output / "mpirun.log";
  std::cerr << "cosim: launching " << runtime::shell_join(cmd) << "\n";
  const pid_t mpirun = supervisor.start(child);

  const auto finish = [&](ExitCode code, const std::string& message) {
    std::cerr << "cosim: error: " << message << "\n";
    std::ofstream(output / "log.txt", std::ios::app) << "[cosim] [error] " << message << "\n";
    record_failure_in_summary(output / "summary.json", code, message, Overrule::anything);
    for (const auto& p : job.participants)
      record_failure_in_summary(output / p.name / "summary.json", ExitCode::participant_failed,
                                "stopped when the MPI job ended (recorded by cosim)");
    return to_int(code);
  };
  const auto started = Clock::now();
  const auto admission_deadline =
      started + milliseconds(static_cast<long>(o.connect_timeout_s * 1000.0)) + launch_slack;
  const auto window_timeout = milliseconds(static_cast<long>(job.window_timeout_s * 1000.0));
  bool coupling = false;
  std::optional<Clock::time_point> run_over_at;
  auto last_look = started;
  // Asked to stop a run that takes checkpoints: the coupler rank is told, it
  // takes one at the next window end and ends the run there (exit 5).
  std::optional<Clock::time_point> stop_forwarded_at;
  for (;;) {
    if (runtime::stop_requested() && !stop_forwarded_at) {
      const auto coupler = coupler_rank(mpirun);
      if (o.checkpoint_every.empty() || !coupler) {
        stop_job(supervisor, mpirun);
        return finish(ExitCode::participant_failed,
                      fmt::format("{}; the MPI job was stopped", runtime::describe_stop()));
      }
      ::kill(*coupler, SIGTERM);
      stop_forwarded_at = Clock::now();
      std::cerr << "cosim: " << runtime::describe_stop()
                << "; the run stops at a checkpoint at the next window end\n";
    }
    if (stop_forwarded_at && Clock::now() - *stop_forwarded_at > window_timeout + stop_grace) {
      stop_job(supervisor, mpirun);
      return finish(ExitCode::participant_failed,
                    fmt::format("{}; the run did not stop at a checkpoint within window_timeout "
                                "({} s); the MPI job was stopped",
                                runtime::describe_stop(), job.window_timeout_s));
    }
    const auto now = Clock::now();
    if (now - last_look > milliseconds(250)) {
      last_look = now;
      if (const auto status = read_status(output / "summary.json")) {
        coupling = coupling || status->coupling;
        if (status->finished && !run_over_at) run_over_at = now;
      }
    }
    if (!coupling && !run_over_at && now > admission_deadline) {
      const std::string stopped = stopped_ranks(processes_below(mpirun));
      stop_job(supervisor, mpirun);
      return finish(ExitCode::participant_failed,
                    fmt::format("the MPI job did not get past its start within the connect "
                                "timeout ({} s){}; the MPI job was stopped",
                                o.connect_timeout_s,
                                stopped.empty() ? " (a rank that never reaches MPI_Init holds "
                                                  "every other rank in it)"
                                                : ": " + stopped));
    }
    if (run_over_at && now - *run_over_at > window_timeout + stop_grace) {
      std::string names;
      for (const auto& p : job.participants) {
        const auto status = read_status(output / p.name / "summary.json");
        if (!status || !status->finished) names += (names.empty() ? "'" : ", '") + p.name + "'";
      }
      stop_job(supervisor, mpirun);
      return finish(ExitCode::participant_failed,
                    fmt::format("participant(s) {} did not exit within window_timeout ({} s) "
                                "after the end of the run; the MPI job was stopped",
                                names.empty() ? "(unknown)" : names, job.window_timeout_s));
    }
    const auto exits =
        supervisor.wait_all(milliseconds(100), stop_forwarded_at ? nullptr : &runtime::stop_flag());
    if (exits.empty()) continue;
    const runtime::ChildExit& e = exits.front();
    if (e.success()) return 0;
    // A participant rank that died is the cause (mpirun then stops the others,
    // and the coupler rank may have blamed one of those), and so is one that
    // refused its input before the coupling began (its MPI_Abort reaches the
    // coupler rank as a signal); otherwise the coupler rank's own account,
    // when it could give one.
    const std::string dead = dead_rank_report(job, child.log_file);
    const auto failed = dead.empty() && !coupling ? failed_participant(job, output) : std::nullopt;
    const auto blame = [&] {
      const int c = failed->first;
      return finish(
          c == 2 || c == 3 || c == 4 ? static_cast<ExitCode>(c) : ExitCode::participant_failed,
          failed->second);
    };
    if (failed && failed->first == to_int(ExitCode::bad_input)) return blame();
    const auto status = read_status(output / "summary.json");
    if (dead.rfind("participant", 0) != 0 && status && status->finished && status->exit_code != 0) {
      std::cerr << "cosim: error: " << status->message << "\n";
      return status->exit_code;
    }
    if (failed) return blame();
    const int s = e.exit_status;
    const ExitCode code = !dead.empty() || !(s == 2 || s == 3 || s == 4)
                              ? ExitCode::participant_failed
                              : static_cast<ExitCode>(s);
    return finish(code, fmt::format("mpirun {}{}; see {}", e.describe(),
                                    dead.empty() ? "" : ": " + dead, child.log_file.string()));
  }
}

}  // namespace cosim::app
