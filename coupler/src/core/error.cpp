#include "cosim/error.hpp"

#include <fmt/format.h>

namespace cosim {

namespace {

std::string located_message(const SourceLocation& where, const std::string& key_path,
                            const std::string& what) {
  std::string prefix = where.file.empty() ? std::string("<input>") : where.file;
  if (where.line > 0) prefix += fmt::format(":{}:{}", where.line, where.column);
  if (key_path.empty()) return fmt::format("{}: {}", prefix, what);
  return fmt::format("{}: key '{}': {}", prefix, key_path, what);
}

}  // namespace

InputError::InputError(const SourceLocation& where, const std::string& key_path,
                       const std::string& what)
    : Error(ExitCode::bad_input, located_message(where, key_path, what)),
      where_(where),
      key_path_(key_path) {}

}  // namespace cosim
