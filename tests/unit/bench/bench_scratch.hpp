#pragma once

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "bench/backend_catalog.hpp"
#include "scratch_directory.hpp"

namespace cosim::bench::testing {

// A fresh directory per test (removed at the end) that files are written into.
class Scratch : public cosim::testing::ScratchDirectory {
 public:
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto file = path() / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }
};

// A registered backend's descriptor (build/share/cosim/backends/<name>.yaml).
inline const BackendDescriptor& backend(const std::string& name) {
  const BackendDescriptor* b = registered_backends().find(name);
  if (b == nullptr) throw std::runtime_error("no registered backend '" + name + "'");
  return *b;
}

}  // namespace cosim::bench::testing
