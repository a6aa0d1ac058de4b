#include "openfoam/foam/foam_application.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "cosim/error.hpp"
#include "cosim/io/tail_lines.hpp"
#include "cosim/runtime/mpi_launch_environment.hpp"
#include "cosim/runtime/stop_request.hpp"
#include "cosim/runtime/supervisor.hpp"

namespace openfoam {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

std::size_t size_of_file(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  return ec ? 0 : static_cast<std::size_t>(size);
}

// The file's bytes from `offset` to its current end.
std::string read_from(const std::filesystem::path& path, std::size_t offset) {
  const std::size_t size = size_of_file(path);
  if (size <= offset) return {};
  std::string bytes(size - offset, '\0');
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(offset));
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return bytes;
}

// Reads a growing log (the application appends to it) from where it was
// last read, line by line.
class LogFollower {
 public:
  LogFollower(std::filesystem::path path, std::size_t offset)
      : path_(std::move(path)), offset_(offset) {}

  // Whether a line starting with `prefix` has appeared since the last call.
  bool saw_line_starting(std::string_view prefix) {
    const std::string chunk = read_from(path_, offset_);
    pending_ += chunk;
    offset_ += chunk.size();
    bool seen = false;
    std::size_t start = 0;
    for (std::size_t end; (end = pending_.find('\n', start)) != std::string::npos;
         start = end + 1) {
      if (std::string_view(pending_).substr(start, end - start).starts_with(prefix)) seen = true;
    }
    pending_.erase(0, start);
    return seen;
  }

 private:
  std::filesystem::path path_;
  std::size_t offset_ = 0;
  std::string pending_;
};

// Whether the log written from `offset` on reports a fatal error.
bool log_has_fatal_error(const std::filesystem::path& log_file, std::size_t offset) {
  return read_from(log_file, offset).find("FOAM FATAL") != std::string::npos;
}

[[noreturn]] void throw_failed(const std::string& name, const std::string& how,
                               const std::filesystem::path& case_dir,
                               const std::filesystem::path& log_file) {
  std::string message =
      fmt::format("OpenFOAM's {} {} (case kept for inspection in {}); last lines of {}:", name, how,
                  case_dir.string(), log_file.string());
  for (const std::string& line : cosim::tail_lines(log_file, 20)) message += "\n  " + line;
  throw cosim::Error(cosim::ExitCode::participant_failed, message);
}

}  // namespace

ApplicationTiming run_application(const Installation& installation, const std::string& name,
                                  std::vector<std::string> arguments,
                                  const std::filesystem::path& case_dir,
                                  const std::filesystem::path& log_file, int processes,
                                  std::chrono::seconds timeout) {
  arguments.insert(arguments.begin(), {"-case", case_dir.string()});
  std::filesystem::path program = installation.application(name);
  cosim::runtime::ChildSpec child{name, program, {}, log_file};
  if (processes > 1) {
    arguments.push_back("-parallel");
    arguments.insert(arguments.begin(),
                     {"-np", std::to_string(processes), "--bind-to", "none", program.string()});
    child.executable = installation.application("mpirun");
    if (::geteuid() == 0)
      child.environment = {{"OMPI_ALLOW_RUN_AS_ROOT", "1"},
                           {"OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1"}};
  }
  child.args = std::move(arguments);
  // The adapter on a rank of a coupled MPI job: OpenFOAM is a job of its
  // own, not a part of the adapter's.
  if (cosim::runtime::launched_as_mpi_rank())
    child.environment_left_out = cosim::runtime::mpi_launch_variable_prefixes();
  const std::size_t log_start = size_of_file(log_file);
  cosim::runtime::Supervisor supervisor;
  const Clock::time_point launched = Clock::now();
  supervisor.start(child);
  LogFollower log(log_file, log_start);
  Clock::time_point first_step{};
  bool stepping = false;
  cosim::runtime::ChildExit exit;
  for (auto pause = std::chrono::microseconds(200);;
       pause = std::min(pause * 2, std::chrono::microseconds(5000))) {
    const auto exits = supervisor.reap();
    if (!stepping && log.saw_line_starting("Time = ")) {
      stepping = true;
      first_step = Clock::now();
    }
    if (!exits.empty()) {
      exit = exits.front();
      break;
    }
    if (cosim::runtime::stop_requested()) {
      supervisor.stop_all(std::chrono::milliseconds(2000));
      throw cosim::Error(cosim::ExitCode::participant_failed,
                         fmt::format("{} (while {} ran)", cosim::runtime::describe_stop(), name));
    }
    if (Clock::now() - launched > timeout) {
      supervisor.stop_all(std::chrono::milliseconds(2000));
      throw_failed(name,
                   fmt::format("did not finish within {} s (stopped; a hang or a far too long "
                               "window: the case's `window_timeout`)",
                               timeout.count()),
                   case_dir, log_file);
    }
    std::this_thread::sleep_for(stepping ? std::chrono::microseconds(5000) : pause);
  }
  const Clock::time_point ended = Clock::now();
  if (!exit.success()) throw_failed(name, exit.describe(), case_dir, log_file);
  if (log_has_fatal_error(log_file, log_start)) {
    throw_failed(name, "reported a FOAM FATAL error", case_dir, log_file);
  }
  ApplicationTiming timing;
  timing.total = seconds_between(launched, ended);
  timing.startup = stepping ? seconds_between(launched, first_step) : timing.total;
  timing.stepping = timing.total - timing.startup;
  return timing;
}

std::string application_output(const Installation& installation, const std::string& name,
                               std::vector<std::string> arguments,
                               const std::filesystem::path& case_dir,
                               const std::filesystem::path& log_file) {
  const std::size_t start = size_of_file(log_file);
  run_application(installation, name, std::move(arguments), case_dir, log_file);
  return read_from(log_file, start);
}

}  // namespace openfoam
