#pragma once

// A solver program of the build run on a case, on its own or under mpirun,
// for the tests that compare a decomposed run's files with one process's.
#include <filesystem>
#include <string>
#include <vector>

#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {

// `program` --config `config` --output `output`: under `mpirun -np ranks`
// (oversubscribed), or on its own when ranks is 0.
inline ProcessResult run_launched(const std::string& program, const std::filesystem::path& config,
                                  const std::filesystem::path& output, int ranks) {
  std::vector<std::string> args;
  if (ranks > 0) args = {MPIEXEC, "--oversubscribe", "-np", std::to_string(ranks)};
  for (const std::string& a : {binary(program).string(), std::string("--config"), config.string(),
                               std::string("--output"), output.string()})
    args.push_back(a);
  return run(args, std::chrono::seconds(120));
}

// `text` as dir/case.yaml.
inline std::filesystem::path write_case(const std::filesystem::path& dir, const std::string& text) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "case.yaml";
  write_text(file, text);
  return file;
}

}  // namespace cosim::testing
