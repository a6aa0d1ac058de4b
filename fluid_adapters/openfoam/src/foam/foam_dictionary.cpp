#include "openfoam/foam/foam_dictionary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <vector>

#include "cosim/error.hpp"
#include "openfoam/foam/foam_application.hpp"

namespace openfoam {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void bad_entry(const fs::path& file, const std::string& entry,
                            const std::string& why) {
  throw cosim::InputError(cosim::SourceLocation{file.string(), 0, 0}, entry, why);
}

// The whitespace-separated numbers of `text` from its end back to the first
// token that is not one (dimensions in brackets and keywords stop it).
std::vector<double> trailing_numbers(std::string_view text) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() &&
           std::string_view(" \t\n\r();").find(text[i]) != std::string_view::npos)
      ++i;
    std::size_t j = i;
    while (j < text.size() &&
           std::string_view(" \t\n\r();").find(text[j]) == std::string_view::npos)
      ++j;
    if (j > i) tokens.push_back(text.substr(i, j - i));
    i = j;
  }
  std::vector<double> numbers;
  for (auto t = tokens.rbegin(); t != tokens.rend(); ++t) {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(t->data(), t->data() + t->size(), v);
    if (ec != std::errc() || end != t->data() + t->size()) break;
    numbers.push_back(v);
  }
  std::reverse(numbers.begin(), numbers.end());
  return numbers;
}

}  // namespace

std::string dictionary_value(const DictionaryQuery& query, const fs::path& file,
                             const std::string& entry) {
  std::error_code ec;
  if (!fs::is_regular_file(query.case_dir / file, ec)) {
    bad_entry(query.case_dir / file, entry, "missing: the file is not in the case");
  }
  std::string output;
  try {
    output = application_output(
        query.installation, "foamDictionary",
        {"-precision", "17", (query.case_dir / file).string(), "-entry", entry, "-value"},
        query.case_dir, query.log_file);
  } catch (const cosim::Error&) {
    bad_entry(query.case_dir / file, entry,
              fmt::format("OpenFOAM's foamDictionary finds no such entry (see {})",
                          query.log_file.string()));
  }
  // The value is the output's last line (OpenFOAM may warn before it).
  while (!output.empty() && std::isspace(static_cast<unsigned char>(output.back())))
    output.pop_back();
  const std::size_t line = output.rfind('\n');
  return line == std::string::npos ? output : output.substr(line + 1);
}

void set_dictionary_entry(const DictionaryQuery& query, const fs::path& file,
                          const std::string& entry, const std::string& value) {
  run_application(query.installation, "foamDictionary",
                  {(query.case_dir / file).string(), "-entry", entry, "-set", value},
                  query.case_dir, query.log_file);
}

double scalar_value(std::string_view value, const fs::path& file, const std::string& entry) {
  const std::vector<double> numbers = trailing_numbers(value);
  if (numbers.empty()) {
    bad_entry(file, entry, fmt::format("expected a number, found '{}'", value));
  }
  return numbers.back();
}

Vector3 vector_value(std::string_view value, const fs::path& file, const std::string& entry) {
  const std::vector<double> numbers = trailing_numbers(value);
  if (numbers.size() < 3) {
    bad_entry(file, entry, fmt::format("expected a vector (x y z), found '{}'", value));
  }
  return {numbers[numbers.size() - 3], numbers[numbers.size() - 2], numbers.back()};
}

}  // namespace openfoam
