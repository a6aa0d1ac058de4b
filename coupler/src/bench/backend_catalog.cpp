#include "bench/backend_catalog.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "cosim/runtime/supervisor.hpp"

namespace cosim::bench {

namespace fs = std::filesystem;

BackendCatalog BackendCatalog::load(const fs::path& directory) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec))
    throw InputError(
        fmt::format("{}: no directory of backend descriptors (each backend registers "
                    "its descriptor with cosim_register_backend; build the project)",
                    directory.string()));
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(directory))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  BackendCatalog catalog;
  catalog.directory_ = directory;
  for (const auto& file : files) {
    BackendDescriptor d = load_backend_descriptor(file);
    if (d.name != file.stem().string())
      throw InputError(
          fmt::format("{}: the descriptor of '{}' is registered as '{}' (its file "
                      "name); give them one name",
                      file.string(), d.name, file.stem().string()));
    const std::string name = d.name;
    catalog.backends_.emplace(name, std::move(d));
  }
  if (catalog.backends_.empty())
    throw InputError(fmt::format("{}: no backend descriptor (*.yaml)", directory.string()));
  for (const auto& [name, d] : catalog.backends_) {
    if (!d.is_soil()) continue;
    if (catalog.soil_ != nullptr)
      throw InputError(
          fmt::format("{}: two backends take the soil's side of the pairings ({} and "
                      "{}); one may",
                      directory.string(), catalog.soil_->name, name));
    catalog.soil_ = &d;
  }
  for (const auto& [name, d] : catalog.backends_) {
    if (!d.is_fluid()) continue;
    if (catalog.soil_ == nullptr || !catalog.soil_->soil_pairings.count(d.fluid_pairing->kind))
      throw InputError(
          fmt::format("{}: the {} pairing of '{}' has no soil side (a registered "
                      "soil backend's soil_pairings.{})",
                      d.file.string(), d.fluid_pairing->kind, name, d.fluid_pairing->kind));
  }
  return catalog;
}

const BackendDescriptor* BackendCatalog::find(const std::string& name) const {
  const auto it = backends_.find(name);
  return it != backends_.end() ? &it->second : nullptr;
}

std::vector<std::string> BackendCatalog::names() const {
  std::vector<std::string> out;
  for (const auto& [name, d] : backends_) out.push_back(name);
  return out;
}

std::string BackendCatalog::names_text() const {
  return fmt::format("{}", fmt::join(names(), ", "));
}

fs::path registered_backends_directory() {
  return runtime::self_directory() / ".." / "share" / "cosim" / "backends";
}

const BackendCatalog& registered_backends() {
  static const BackendCatalog catalog = BackendCatalog::load(registered_backends_directory());
  return catalog;
}

std::set<std::string> programs_starting_their_processes() {
  std::set<std::string> programs;
  try {
    const BackendCatalog& catalog = registered_backends();
    for (const auto& name : catalog.names())
      if (const BackendDescriptor* d = catalog.find(name); d && d->ranks_are_solver_processes)
        programs.insert(fs::path(d->executable).filename().string());
  } catch (const Error& e) {
    spdlog::warn(
        "the registered backends could not be read ({}): every participant's `ranks` "
        "are taken as MPI ranks of its program",
        e.what());
  }
  return programs;
}

}  // namespace cosim::bench
