#pragma once

#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace cosim::bench::testing
