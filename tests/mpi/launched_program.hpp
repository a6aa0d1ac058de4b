#pragma once

// A solver program of the build run on a case, on its own or under mpirun,
// for the tests that compare a decomposed run's files with one process's.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {

// `program` --config `config` --output `output`: under `mpirun -np ranks`
// (oversubscribed), or on its own when ranks is 0.
inline ProcessResult run_launched(const std::string& program, const std::filesystem::path& config,
                                  const std::filesystem::path& output, int ranks,
                                  const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args;
  if (ranks > 0) args = {MPIEXEC, "--oversubscribe", "-np", std::to_string(ranks)};
  for (const std::string& a : {binary(program).string(), std::string("--config"), config.string(),
                               std::string("--output"), output.string()})
    args.push_back(a);
  args.insert(args.end(), extra.begin(), extra.end());
  return run(args, std::chrono::seconds(120));
}

// `text` as dir/case.yaml.
inline std::filesystem::path write_case(const std::filesystem::path& dir, const std::string& text) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "case.yaml";
  write_text(file, text);
  return file;
}

// `program` on `ranks` ranks refuses the case `text` with exit 2, its
// summary naming case.yaml and `key`, and writes no `first_output`.
inline void expect_refused_on_ranks(const std::string& program, const std::string& text,
                                    const std::string& key, int ranks,
                                    const std::string& first_output) {
  const std::filesystem::path dir = fresh_directory(program + "_ranks_refused");
  const std::filesystem::path config = write_case(dir, text);
  const ProcessResult result = run_launched(program, config, dir / "run", ranks);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  const std::string summary = read_text(dir / "run" / "summary.json");
  EXPECT_NE(summary.find("bad_input"), std::string::npos) << summary;
  EXPECT_NE(summary.find("case.yaml: key '" + key + "'"), std::string::npos) << summary;
  EXPECT_FALSE(std::filesystem::exists(dir / "run" / first_output));
}

// `program` on 2 ranks, given an output directory an earlier run holds,
// exits 2 and leaves it as it was: no ranks/ and no summary.
inline void expect_directory_in_use_kept(const std::string& program, const std::string& text) {
  const std::filesystem::path dir = fresh_directory(program + "_ranks_in_use");
  const std::filesystem::path config = write_case(dir, text);
  std::filesystem::create_directories(dir / "run");
  write_text(dir / "run" / "earlier.txt", "an earlier run's file\n");
  const ProcessResult result = run_launched(program, config, dir / "run", 2);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_EQ(read_text(dir / "run" / "earlier.txt"), "an earlier run's file\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "run" / "ranks"));
  EXPECT_FALSE(std::filesystem::exists(dir / "run" / "summary.json"));
}

}  // namespace cosim::testing
