#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

// A seeded mutation fuzzer run inside a GoogleTest: every kept regression
// input first, then mutated inputs. An input fails when the target throws
// anything but a cosim::Error, or takes more CPU time than the hang limit
// (an endless loop: a watchdog stops the process at 30 times the limit of
// wall time); a crash prints the input before the process dies.
//
// Environment:
//   COSIM_FUZZ_EXECUTIONS  mutated inputs to run (the target's short default
//                          otherwise; 1000000 for a benchmark run)
//   COSIM_FUZZ_SEED        the mutator's seed (default 23)
//   COSIM_FUZZ_SAVE        a directory: each failing input is written to
//                          <dir>/<target>/ (tests/data/fuzz keeps them as
//                          regression inputs)
namespace cosim::testing {

class Mutator;

struct FuzzTarget {
  std::string name;  // its regression inputs are tests/data/fuzz/<name>/*
  std::function<void(const std::string& input)> run;
  std::vector<std::string> seeds;
  std::vector<std::string> tokens;  // for the mutator
  // Makes an input from one of the corpus; Mutator::mutate when empty.
  std::function<std::string(const std::string& input, Mutator& mutator)> mutate;
  std::size_t max_size = 1 << 16;  // bytes of a mutated input
  std::uint64_t default_executions = 1000;
  std::chrono::milliseconds hang_limit{1000};  // CPU time of one input
};

struct FuzzReport {
  std::uint64_t regression_inputs = 0;
  std::uint64_t executions = 0;       // mutated inputs
  std::uint64_t crashes = 0;          // exceptions other than cosim::Error
  std::uint64_t hangs = 0;            // inputs that took more CPU time than the hang limit
  double seconds = 0.0;               // wall time of the run
  double slowest_seconds = 0.0;       // CPU time of the slowest input
  std::vector<std::string> failures;  // what went wrong, with the input

  std::string summary(const std::string& target) const;
};

FuzzReport fuzz(const FuzzTarget& target);

// The kept regression inputs of `target`: tests/data/fuzz/<target>/*.
std::vector<std::string> regression_inputs(const std::string& target);

// Every regular file under `directory` whose name ends in `extension`.
std::vector<std::filesystem::path> files_under(const std::filesystem::path& directory,
                                               const std::string& extension);

}  // namespace cosim::testing
