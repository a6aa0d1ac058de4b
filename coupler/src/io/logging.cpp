#include "cosim/io/logging.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <string>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"

namespace cosim {

namespace {

constexpr const char* line_format = "[%Y-%m-%d %H:%M:%S.%e] [%n] [%l] %v";

spdlog::level::level_enum level_of(Verbosity verbosity) {
  switch (verbosity) {
    case Verbosity::quiet:
      return spdlog::level::warn;
    case Verbosity::normal:
      return spdlog::level::info;
    case Verbosity::verbose:
      return spdlog::level::debug;
    case Verbosity::trace:
      return spdlog::level::trace;
  }
  return spdlog::level::info;
}

}  // namespace

Verbosity parse_verbosity(std::string_view text) {
  if (text == "quiet") return Verbosity::quiet;
  if (text == "normal") return Verbosity::normal;
  if (text == "verbose") return Verbosity::verbose;
  if (text == "trace") return Verbosity::trace;
  throw InputError("unknown verbosity '" + std::string(text) +
                   "' (expected quiet, normal, verbose or trace)");
}

std::shared_ptr<spdlog::logger> init_logging(const std::filesystem::path& output_dir,
                                             std::string_view program_name, Verbosity verbosity) {
  create_output_directory(output_dir);
  const std::string name(program_name);
  const std::filesystem::path log_path = output_dir / "log.txt";

  auto console = std::make_shared<spdlog::sinks::stderr_sink_mt>();
  console->set_level(level_of(verbosity));
  std::shared_ptr<spdlog::sinks::basic_file_sink_mt> file;
  try {
    file = std::make_shared<spdlog::sinks::basic_file_sink_mt>(log_path.string(), true);
  } catch (const spdlog::spdlog_ex& e) {
    throw Error(ExitCode::bad_input,
                "cannot open log file '" + log_path.string() + "': " + e.what());
  }
  const auto file_level = std::min(level_of(verbosity), spdlog::level::info);
  file->set_level(file_level);

  auto logger = std::make_shared<spdlog::logger>(name, spdlog::sinks_init_list{console, file});
  logger->set_pattern(line_format);
  logger->set_level(std::min(console->level(), file_level));
  logger->flush_on(spdlog::level::trace);

  spdlog::drop(name);
  spdlog::set_default_logger(logger);
  return logger;
}

}  // namespace cosim
