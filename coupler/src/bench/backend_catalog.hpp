#pragma once

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "bench/backend_descriptor.hpp"
#include "cosim/error.hpp"

namespace cosim::bench {

// The backends `cosim bench` can run: one descriptor per registered backend,
// read from one directory (the build's or installation's
// share/cosim/backends/, where cosim_register_backend copies them).
class BackendCatalog {
 public:
  // Reads and validates every `*.yaml` in `directory`. Throws InputError at
  // the first malformed descriptor, and when two give one name, a file's
  // name differs from the name it gives, none is a soil, or the directory
  // holds none.
  static BackendCatalog load(const std::filesystem::path& directory);

  BackendCatalog(BackendCatalog&&) = default;
  BackendCatalog(const BackendCatalog&) = delete;  // soil() points into its own map
  BackendCatalog& operator=(const BackendCatalog&) = delete;

  // nullptr when no backend has the name.
  const BackendDescriptor* find(const std::string& name) const;
  // Sorted: "coupler, ice, mpm, openfoam, swe".
  std::vector<std::string> names() const;
  std::string names_text() const;
  // The backend that takes the soil's side of the pairings (mpm); nullptr
  // when none is registered.
  const BackendDescriptor* soil() const { return soil_; }
  const std::filesystem::path& directory() const { return directory_; }

 private:
  BackendCatalog() = default;

  std::filesystem::path directory_;
  std::map<std::string, BackendDescriptor> backends_;
  const BackendDescriptor* soil_ = nullptr;
};

// The registered backends, read once from share/cosim/backends/ next to the
// running program (<bin>/../share/cosim/backends).
const BackendCatalog& registered_backends();
std::filesystem::path registered_backends_directory();

// The executables (file names) of the registered backends whose job
// `ranks` are their solver's processes (`ranks: solver_processes`), for
// job::load_job; empty, with a warning, when the registry cannot be read.
std::set<std::string> programs_starting_their_processes();

}  // namespace cosim::bench
