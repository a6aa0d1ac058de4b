#include "openfoam/foam/installation.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <sstream>

#include "cosim/error.hpp"

namespace openfoam {

namespace {

bool is_executable(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

std::filesystem::path find_on_path(const std::string& name) {
  std::vector<std::filesystem::path> directories;
  if (const char* path = std::getenv("PATH")) {
    std::stringstream entries(path);
    std::string entry;
    while (std::getline(entries, entry, ':')) {
      if (!entry.empty()) directories.emplace_back(entry);
    }
  }
  for (const auto& directory : directories) {
    if (is_executable(directory / name)) return directory / name;
  }
  return {};
}

}  // namespace

std::string installation_hint() {
  return "install Debian's OpenFOAM v1912: apt-get install openfoam (the project's set-up "
         "script .ci/setup does)";
}

const std::filesystem::path& Installation::application(const std::string& name) const {
  const auto found = applications.find(name);
  if (found == applications.end()) {
    throw cosim::Error(cosim::ExitCode::internal_error,
                       fmt::format("OpenFOAM application '{}' was not looked up", name));
  }
  return found->second;
}

Installation find_installation(const std::vector<std::string>& names) {
  Installation installation;
  for (const std::string& name : names) {
    const auto path = find_on_path(name);
    if (path.empty()) {
      throw cosim::InputError(
          fmt::format("OpenFOAM is not installed: no '{}' on PATH; {}", name, installation_hint()));
    }
    installation.applications[name] = path;
  }
  const char* set = std::getenv("WM_PROJECT_DIR");
  installation.project_dir =
      set && *set ? std::filesystem::path(set) : std::filesystem::path("/usr/share/openfoam");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(installation.project_dir / "etc" / "controlDict", ec)) {
    throw cosim::InputError(fmt::format(
        "OpenFOAM's etc directory is missing: no {} (WM_PROJECT_DIR {}); {}",
        (installation.project_dir / "etc" / "controlDict").string(),
        set && *set ? "as set" : "unset, the Debian location tried", installation_hint()));
  }
  ::setenv("WM_PROJECT_DIR", installation.project_dir.c_str(), 1);
  // The applications warn in their logs when PWD is not the working directory.
  std::error_code cwd_error;
  const std::filesystem::path cwd = std::filesystem::current_path(cwd_error);
  if (!cwd_error) ::setenv("PWD", cwd.c_str(), 1);
  return installation;
}

}  // namespace openfoam
