#include "private_directory.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

#include "cosim/error.hpp"

namespace cosim::com {

namespace fs = std::filesystem;

namespace {

constexpr const char* owner_file = "owner";

// The temporary root: $TMPDIR when short enough that an ipc socket path
// under it fits a Unix socket address (108 bytes), else /tmp.
fs::path temporary_root() {
  const char* base = std::getenv("TMPDIR");
  return (base && *base && std::strlen(base) < 60) ? fs::path(base) : fs::path("/tmp");
}

// Field 22 of /proc/<pid>/stat: when the process started, in clock ticks
// since boot; with the pid it names one process even after pids wrap.
std::optional<unsigned long long> start_time_of(pid_t pid) {
  std::ifstream in(fmt::format("/proc/{}/stat", pid));
  std::string stat;
  if (!std::getline(in, stat)) return std::nullopt;
  const auto name_end = stat.rfind(')');  // the command name may hold spaces
  if (name_end == std::string::npos) return std::nullopt;
  std::istringstream fields(stat.substr(name_end + 2));
  std::string field;
  for (int i = 3; i < 22 && fields >> field; ++i) {
  }
  unsigned long long start = 0;
  if (!(fields >> start)) return std::nullopt;
  return start;
}

bool owner_is_running(const fs::path& directory) {
  std::ifstream in(directory / owner_file);
  long pid = 0;
  unsigned long long start = 0;
  if (!(in >> pid >> start) || pid <= 0) return true;  // not (yet) ours to judge
  if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) return false;
  if (start == 0) return true;  // its start time was not known: the pid lives
  const auto running_start = start_time_of(static_cast<pid_t>(pid));
  return !running_start || *running_start == start;
}

}  // namespace

std::size_t remove_abandoned_directories(const fs::path& root, const std::string& prefix) {
  std::size_t removed = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(root, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix + "-", 0) != 0) continue;
    struct stat st {};
    if (::lstat(entry.path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::geteuid())
      continue;
    if (!fs::exists(entry.path() / owner_file, ec) || owner_is_running(entry.path())) continue;
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);
    if (!ignored) {
      ++removed;
      spdlog::info("removed {}, left by a coupler that did not stop cleanly",
                   entry.path().string());
    }
  }
  return removed;
}

PrivateDirectory PrivateDirectory::create(const std::string& prefix) {
  const fs::path root = temporary_root();
  remove_abandoned_directories(root, prefix);
  std::string pattern = (root / (prefix + "-XXXXXX")).string();
  // mkdtemp creates the directory with mode 0700.
  if (::mkdtemp(pattern.data()) == nullptr)
    throw Error(ExitCode::bad_input, fmt::format("cannot create a private directory for ipc "
                                                 "endpoints under {}: {}",
                                                 root.string(), std::strerror(errno)));
  PrivateDirectory directory{fs::path(pattern)};
  std::ofstream(directory.path_ / owner_file)
      << ::getpid() << " " << start_time_of(::getpid()).value_or(0) << "\n";
  return directory;
}

PrivateDirectory::PrivateDirectory(PrivateDirectory&& other) noexcept
    : path_(std::move(other.path_)) {
  other.path_.clear();
}

PrivateDirectory::~PrivateDirectory() {
  if (path_.empty()) return;
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

}  // namespace cosim::com
