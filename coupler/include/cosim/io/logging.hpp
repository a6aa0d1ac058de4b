#pragma once

#include <spdlog/logger.h>

#include <filesystem>
#include <memory>
#include <string_view>

namespace cosim {

// How much a run reports on the console.
enum class Verbosity {
  quiet,    // warnings and errors
  normal,   // + progress (info)
  verbose,  // + debug
  trace,    // everything
};

// Parses "quiet" | "normal" | "verbose" | "trace"; throws InputError otherwise.
Verbosity parse_verbosity(std::string_view text);

// Sets up the process's default spdlog logger, named `program_name`, with two
// sinks in the same plain format `[time] [program] [level] message`:
// stderr at `verbosity`, and `<output_dir>/log.txt` (truncated) that keeps at
// least info-level lines even when the console is quiet, flushed after every
// line so a crashed process leaves its last words behind. Creates
// `output_dir` when missing. Calling it again replaces the previous default
// logger (and closes its file).
std::shared_ptr<spdlog::logger> init_logging(const std::filesystem::path& output_dir,
                                             std::string_view program_name,
                                             Verbosity verbosity = Verbosity::normal);

}  // namespace cosim
