#include "cosim/error.hpp"

#include <fmt/format.h>

namespace cosim {

namespace {

// A message quotes what the user wrote: a file name, a key, a value. Absurd
// input (a megabyte-long name) must not make an absurd message: each part
// keeps its beginning and end.
std::string abbreviated(const std::string& text, std::size_t limit) {
  if (text.size() <= limit) return text;
  const std::size_t half = limit / 2;
  return fmt::format("{}[... {} bytes ...]{}", text.substr(0, half), text.size() - 2 * half,
                     text.substr(text.size() - half));
}

constexpr std::size_t name_limit = 256;
constexpr std::size_t text_limit = 2048;

std::string located_message(const SourceLocation& where, const std::string& key_path,
                            const std::string& what) {
  std::string prefix =
      where.file.empty() ? std::string("<input>") : abbreviated(where.file, name_limit);
  if (where.line > 0) prefix += fmt::format(":{}:{}", where.line, where.column);
  if (key_path.empty()) return fmt::format("{}: {}", prefix, abbreviated(what, text_limit));
  return fmt::format("{}: key '{}': {}", prefix, abbreviated(key_path, name_limit),
                     abbreviated(what, text_limit));
}

}  // namespace

InputError::InputError(const SourceLocation& where, const std::string& key_path,
                       const std::string& what)
    : Error(ExitCode::bad_input, located_message(where, key_path, what)),
      where_(where),
      key_path_(key_path) {}

InputError::InputError(const std::string& what)
    : Error(ExitCode::bad_input, abbreviated(what, text_limit)) {}

}  // namespace cosim
