#pragma once

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "replaced_text.hpp"
#include "run_process.hpp"

namespace cosim::testing {

// Runs the coupled job configs/openfoam_coupled/<config> (job.yaml,
// soil.yaml, water.yaml, whose job ends at 2 s) to `end_time` in a fresh
// test directory named `name`, with its outputs in <directory>/run.
// Returns the directory; the run's result goes to `result`.
inline std::filesystem::path run_shortened_coupled_job(const std::string& config,
                                                       const std::string& name, double end_time,
                                                       std::chrono::seconds timeout,
                                                       ProcessResult& result) {
  namespace fs = std::filesystem;
  const fs::path source = fs::path(COSIM_SOURCE_DIR) / "configs/openfoam_coupled" / config;
  const fs::path dir = fresh_directory(name);
  write_text(dir / "job.yaml", replaced(read_text(source / "job.yaml"), "end_time: 2.0",
                                        fmt::format("end_time: {}", end_time)));
  for (const char* f : {"soil.yaml", "water.yaml"}) write_text(dir / f, read_text(source / f));
  result = run({binary("cosim").string(), "run", (dir / "job.yaml").string(), "--output",
                (dir / "run").string()},
               timeout);
  return dir;
}

}  // namespace cosim::testing
