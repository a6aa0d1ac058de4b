#include "openfoam/foam/field_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "openfoam/foam/foam_file_header.hpp"

namespace openfoam {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail_reading(const std::string& message) {
  throw cosim::Error(cosim::ExitCode::participant_failed, message);
}

std::string read_whole_file(const fs::path& file) {
  std::FILE* stream = std::fopen(file.c_str(), "rb");
  if (stream == nullptr) {
    std::string message =
        fmt::format("cannot read OpenFOAM file '{}': {}", file.string(), std::strerror(errno));
    fs::path compressed = file;
    compressed += ".gz";
    std::error_code ignored;
    if (fs::exists(compressed, ignored)) {
      message += fmt::format(" (there is '{}': the case must use writeCompression off)",
                             compressed.string());
    }
    fail_reading(message);
  }
  std::string text;
  std::error_code unknown_size;
  const std::uintmax_t size = fs::file_size(file, unknown_size);
  if (!unknown_size) text.reserve(static_cast<std::size_t>(size));
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, stream)) > 0) text.append(buffer, got);
  const bool failed = std::ferror(stream) != 0;
  std::fclose(stream);
  if (failed) fail_reading(fmt::format("cannot read OpenFOAM file '{}'", file.string()));
  return text;
}

// Characters that end a word or a number: blanks and OpenFOAM's punctuation.
bool is_delimiter(char c) {
  constexpr std::string_view delimiters = " \t\n\r\f\v(){}[];\"";
  return delimiters.find(c) != std::string_view::npos;
}

// A cursor over the text of one OpenFOAM ASCII file. Line numbers are
// counted only when an error is reported, so the value loops stay cheap.
class FoamText {
 public:
  FoamText(const fs::path& file, std::string text) : file_(file), text_(std::move(text)) {}

  // Moves past whitespace and C/C++ comments.
  void skip_blanks() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/') {
        const std::size_t eol = text_.find('\n', pos_);
        pos_ = eol == std::string::npos ? text_.size() : eol + 1;
      } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '*') {
        const std::size_t close = text_.find("*/", pos_ + 2);
        if (close == std::string::npos) fail("expected '*/' closing this comment");
        pos_ = close + 2;
      } else {
        return;
      }
    }
  }

  bool at_end() {
    skip_blanks();
    return pos_ == text_.size();
  }

  // The next significant character, '\0' at the end.
  char peek() { return at_end() ? '\0' : text_[pos_]; }

  bool accept(char c) {
    if (peek() != c) return false;
    ++pos_;
    return true;
  }

  void expect(char c, std::string_view what) {
    if (!accept(c)) fail_expected(what);
  }

  // The next run of non-delimiter characters: a keyword, `List<scalar>`, ...
  std::string_view word() {
    skip_blanks();
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && !is_delimiter(text_[pos_]) && !comment_starts(pos_)) ++pos_;
    return std::string_view(text_).substr(begin, pos_ - begin);
  }

  bool try_scalar(double& value) {
    skip_blanks();
    const char* begin = text_.data() + pos_;
    const char* end = text_.data() + text_.size();
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || !token_ends(stop)) return false;
    pos_ = static_cast<std::size_t>(stop - text_.data());
    return true;
  }

  bool try_label(std::int64_t& value) {
    skip_blanks();
    const char* begin = text_.data() + pos_;
    const char* end = text_.data() + text_.size();
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || !token_ends(stop)) return false;
    pos_ = static_cast<std::size_t>(stop - text_.data());
    return true;
  }

  // Skips the value of an entry whose keyword was just read: a `{...}`
  // dictionary, or tokens up to the `;` outside any brackets.
  void skip_entry_value(std::string_view keyword) {
    if (accept('{')) {
      skip_dictionary_body(keyword);
      return;
    }
    int depth = 0;
    while (true) {
      if (at_end()) fail_expected(fmt::format("';' ending the entry '{}'", keyword));
      const char c = text_[pos_];
      if (c == ';' && depth == 0) {
        ++pos_;
        return;
      }
      // A brace closing the enclosing dictionary: this entry's ';' is missing.
      if (c == '}') fail_expected(fmt::format("';' ending the entry '{}'", keyword));
      if (c == '(' || c == '[') ++depth;
      if (c == ')' || c == ']') --depth;
      if (c == '{') {
        ++pos_;
        skip_dictionary_body(keyword);
      } else {
        step_over_token();
      }
    }
  }

  // Moves past a `#include ...`-style directive line.
  void skip_line() {
    const std::size_t eol = text_.find('\n', pos_);
    pos_ = eol == std::string::npos ? text_.size() : eol + 1;
  }

  std::size_t position() {
    skip_blanks();
    return pos_;
  }

  std::size_t remaining() const { return text_.size() - pos_; }

  [[noreturn]] void fail_at(std::size_t at, std::string_view message) const {
    fail_reading(fmt::format("{}:{}: {}", file_.string(), line_of(at), message));
  }
  [[noreturn]] void fail(std::string_view message) const { fail_at(pos_, message); }
  [[noreturn]] void fail_expected(std::string_view what) {
    skip_blanks();
    fail(fmt::format("expected {}, found {}", what, next_token()));
  }

  // For an entry that was read from `at` up to here.
  [[noreturn]] void fail_not_finite(std::size_t at, std::string_view what) const {
    throw cosim::NumericalError(fmt::format("{}:{}: {} is not finite ('{}')", file_.string(),
                                            line_of(at), what, text_.substr(at, pos_ - at)));
  }

  // The next token as an error message shows it.
  std::string next_token() {
    if (at_end()) return "the end of the file";
    if (is_delimiter(text_[pos_])) return fmt::format("'{}'", text_[pos_]);
    const std::size_t begin = pos_;
    const std::string_view token = word();
    pos_ = begin;
    constexpr std::size_t shown = 32;
    return token.size() > shown ? fmt::format("'{}...'", token.substr(0, shown))
                                : fmt::format("'{}'", token);
  }

 private:
  bool comment_starts(std::size_t at) const {
    return text_[at] == '/' && at + 1 < text_.size() &&
           (text_[at + 1] == '/' || text_[at + 1] == '*');
  }

  bool token_ends(const char* stop) const {
    const auto at = static_cast<std::size_t>(stop - text_.data());
    return at == text_.size() || is_delimiter(text_[at]) || comment_starts(at);
  }

  void step_over_token() {
    if (text_[pos_] == '"') {
      std::size_t at = pos_ + 1;
      while (at < text_.size() && text_[at] != '"') at += text_[at] == '\\' ? 2 : 1;
      if (at >= text_.size()) fail("expected '\"' closing this string");
      pos_ = at + 1;
    } else if (is_delimiter(text_[pos_])) {
      ++pos_;
    } else {
      word();
    }
  }

  // After the opening brace, up to and including the matching one.
  void skip_dictionary_body(std::string_view keyword) {
    int depth = 1;
    while (depth > 0) {
      if (at_end()) fail_expected(fmt::format("'}}' closing '{}'", keyword));
      const char c = text_[pos_];
      if (c == '{') ++depth;
      if (c == '}') --depth;
      step_over_token();
    }
  }

  int line_of(std::size_t at) const {
    const auto end = text_.begin() + static_cast<std::ptrdiff_t>(std::min(at, text_.size()));
    return 1 + static_cast<int>(std::count(text_.begin(), end, '\n'));
  }

  fs::path file_;
  std::string text_;
  std::size_t pos_ = 0;
};

// The FoamFile dictionary, its keyword already read; only its format matters.
void read_header(FoamText& text) {
  text.expect('{', "'{' opening FoamFile");
  while (!text.accept('}')) {
    if (text.at_end()) text.fail_expected("'}' closing FoamFile");
    const std::string_view keyword = text.word();
    if (keyword.empty()) text.fail_expected("a keyword in FoamFile");
    if (keyword == "format") {
      const std::size_t at = text.position();
      const std::string_view format = text.word();
      if (format != "ascii") {
        text.fail_at(at, fmt::format("expected format ascii, found '{}' (the case must use "
                                     "writeFormat ascii)",
                                     format));
      }
    }
    text.skip_entry_value(keyword);
  }
}

// Reads a header when the file starts with one.
void skip_optional_header(FoamText& text) {
  const std::size_t at = text.position();
  const char next = text.peek();
  if (next == '\0' || is_delimiter(next) || std::isdigit(static_cast<unsigned char>(next)) != 0) {
    return;
  }
  const std::string_view keyword = text.word();
  if (keyword != "FoamFile") {
    text.fail_at(at, fmt::format("expected FoamFile or a list, found '{}'", keyword));
  }
  read_header(text);
}

// The kinds of list entry: `read` fills `components` values and returns false
// when the text there is not such an entry.
struct ScalarEntry {
  using Value = double;
  static constexpr std::size_t components = 1;
  static constexpr std::string_view name = "a number";
  static bool read(FoamText& text, double* out) { return text.try_scalar(*out); }
};

struct VectorEntry {
  using Value = double;
  static constexpr std::size_t components = 3;
  static constexpr std::string_view name = "a vector (x y z)";
  static bool read(FoamText& text, double* out) {
    return text.accept('(') && text.try_scalar(out[0]) && text.try_scalar(out[1]) &&
           text.try_scalar(out[2]) && text.accept(')');
  }
};

struct LabelEntry {
  using Value = std::int64_t;
  static constexpr std::size_t components = 1;
  static constexpr std::string_view name = "a label";
  static bool read(FoamText& text, std::int64_t* out) { return text.try_label(*out); }
};

template <class Entry>
void read_entry(FoamText& text, typename Entry::Value* out, std::size_t index,
                std::string_view what) {
  const std::size_t at = text.position();
  if (!Entry::read(text, out)) {
    text.fail_expected(fmt::format("{} as value {} of {}", Entry::name, index + 1, what));
  }
  if constexpr (std::is_floating_point_v<typename Entry::Value>) {
    for (std::size_t c = 0; c < Entry::components; ++c) {
      if (!std::isfinite(out[c]))
        text.fail_not_finite(at, fmt::format("value {} of {}", index + 1, what));
    }
  }
}

// `N ( e ... )` or `N{e}`, N checked against `expected` when given.
template <class Entry>
std::vector<typename Entry::Value> read_list(FoamText& text, std::string_view what,
                                             std::optional<std::size_t> expected) {
  const std::size_t size_at = text.position();
  std::int64_t declared = 0;
  if (!text.try_label(declared) || declared < 0) {
    text.fail_expected(fmt::format("the number of values of {}", what));
  }
  const auto size = static_cast<std::size_t>(declared);
  if (expected && size != *expected) {
    text.fail_at(size_at, fmt::format("expected {} values in {}, found {}", *expected, what, size));
  }
  std::vector<typename Entry::Value> values;
  typename Entry::Value entry[Entry::components];
  if (text.accept('{')) {
    read_entry<Entry>(text, entry, 0, what);
    text.expect('}', fmt::format("'}}' closing the uniform value of {}", what));
    values.resize(size * Entry::components);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = entry[i % Entry::components];
    return values;
  }
  text.expect('(', fmt::format("'(' or '{{' opening {}", what));
  // Capped: a corrupt N must fail as a short list, not as an allocation.
  values.reserve(std::min(size, text.remaining()) * Entry::components);
  for (std::size_t i = 0; i < size; ++i) {
    const char next = text.peek();
    if (next == ')' || next == '\0') {
      text.fail(fmt::format("expected {} values in {}, found {}", size, what, i));
    }
    read_entry<Entry>(text, entry, i, what);
    values.insert(values.end(), entry, entry + Entry::components);
  }
  text.expect(')', fmt::format("')' closing {} after {} values", what, size));
  return values;
}

template <class Entry>
std::vector<double> read_internal_field_of(FoamText& text, std::size_t cells,
                                           std::string_view what) {
  const std::size_t at = text.position();
  const std::string_view form = text.word();
  std::vector<double> values;
  if (form == "uniform") {
    double entry[Entry::components];
    read_entry<Entry>(text, entry, 0, what);
    values.resize(cells * Entry::components);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = entry[i % Entry::components];
  } else if (form == "nonuniform") {
    const std::string_view list_type = Entry::components == 3 ? "List<vector>" : "List<scalar>";
    const std::size_t type_at = text.position();
    const std::string_view found = text.word();
    if (found != list_type) {
      text.fail_at(type_at, fmt::format("expected {} in {}, found '{}'", list_type, what, found));
    }
    values = read_list<Entry>(text, what, cells);
  } else {
    text.fail_at(at, fmt::format("expected uniform or nonuniform in {}, found {}", what,
                                 form.empty() ? text.next_token() : fmt::format("'{}'", form)));
  }
  text.expect(';', fmt::format("';' ending {}", what));
  return values;
}

template <class Entry>
std::vector<typename Entry::Value> read_list_file(const fs::path& file,
                                                  std::optional<std::size_t> entries) {
  FoamText text(file, read_whole_file(file));
  skip_optional_header(text);
  auto values = read_list<Entry>(text, "the list", entries);
  if (!text.at_end()) text.fail_expected("the end of the file after the list");
  return values;
}

void check_finite(const fs::path& file, std::span<const double> values) {
  const auto bad =
      std::find_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); });
  if (bad == values.end()) return;
  throw cosim::NumericalError(fmt::format("'{}' not written: value {} is not finite ({})",
                                          file.string(), bad - values.begin(), *bad));
}

void check_whole_entries(std::span<const double> values, FieldType type, const fs::path& file) {
  if (values.size() % components(type) != 0) {
    throw std::invalid_argument(
        fmt::format("'{}': {} values do not make whole vectors", file.string(), values.size()));
  }
}

std::string header_for(const fs::path& file, std::string_view location,
                       std::string_view class_name) {
  return foam_file_header({.class_name = std::string(class_name),
                           .location = std::string(location),
                           .object = file.filename().string()});
}

// `N\n(\nentry\n...\n)\n` with 17 significant digits.
void append_values(std::string& out, FieldType type, std::span<const double> values) {
  const std::size_t n = components(type);
  auto sink = std::back_inserter(out);
  fmt::format_to(sink, "{}\n(\n", values.size() / n);
  for (std::size_t i = 0; i < values.size(); i += n) {
    if (type == FieldType::vector) {
      fmt::format_to(sink, "({:.17g} {:.17g} {:.17g})\n", values[i], values[i + 1], values[i + 2]);
    } else {
      fmt::format_to(sink, "{:.17g}\n", values[i]);
    }
  }
  out += ")\n";
}

}  // namespace

std::vector<double> read_internal_field(const fs::path& file, FieldType type, std::size_t cells) {
  FoamText text(file, read_whole_file(file));
  while (!text.at_end()) {
    if (text.peek() == '#') {
      text.skip_line();
      continue;
    }
    const std::string_view keyword = text.word();
    if (keyword.empty()) text.fail_expected("a keyword");
    if (keyword == "FoamFile") {
      read_header(text);
    } else if (keyword == "internalField" || keyword == "value") {
      // `value` at the top: a DimensionedField (a cloud's UTrans, UCoeff).
      return type == FieldType::vector ? read_internal_field_of<VectorEntry>(text, cells, keyword)
                                       : read_internal_field_of<ScalarEntry>(text, cells, keyword);
    } else {
      text.skip_entry_value(keyword);
    }
  }
  text.fail_expected("an internalField entry");
}

std::vector<double> read_field_list(const fs::path& file, FieldType type,
                                    std::optional<std::size_t> entries) {
  return type == FieldType::vector ? read_list_file<VectorEntry>(file, entries)
                                   : read_list_file<ScalarEntry>(file, entries);
}

std::vector<std::int64_t> read_label_list(const fs::path& file,
                                          std::optional<std::size_t> entries) {
  return read_list_file<LabelEntry>(file, entries);
}

void write_vol_field(const fs::path& file, std::string_view location, const VolField& field) {
  check_whole_entries(field.values, field.type, file);
  check_finite(file, field.values);
  const bool vector = field.type == FieldType::vector;
  std::string text = header_for(file, location, vector ? "volVectorField" : "volScalarField");
  text += fmt::format("dimensions      {};\n\ninternalField   nonuniform {}\n", field.dimensions,
                      vector ? "List<vector>" : "List<scalar>");
  append_values(text, field.type, field.values);
  text += fmt::format(";\n\nboundaryField\n{{\n{}\n}}\n", field.boundary_field);
  cosim::write_file_atomically(file, text);
}

void write_field_list(const fs::path& file, std::string_view location, FieldType type,
                      std::span<const double> values) {
  check_whole_entries(values, type, file);
  check_finite(file, values);
  std::string text =
      header_for(file, location, type == FieldType::vector ? "vectorField" : "scalarField");
  append_values(text, type, values);
  cosim::write_file_atomically(file, text);
}

void write_label_list(const fs::path& file, std::string_view location,
                      std::span<const std::int64_t> labels) {
  std::string text = header_for(file, location, "labelField");
  auto sink = std::back_inserter(text);
  fmt::format_to(sink, "{}\n(\n", labels.size());
  for (const std::int64_t label : labels) fmt::format_to(sink, "{}\n", label);
  text += ")\n";
  cosim::write_file_atomically(file, text);
}

void write_parcel_positions(const fs::path& file, std::string_view location,
                            std::string_view parcel_type, std::span<const double> xyz,
                            std::span<const std::int64_t> cells) {
  if (xyz.size() != 3 * cells.size()) {
    throw std::invalid_argument(fmt::format("'{}': {} coordinates for {} parcels", file.string(),
                                            xyz.size(), cells.size()));
  }
  check_finite(file, xyz);
  std::string text = header_for(file, location, fmt::format("Cloud<{}>", parcel_type));
  auto sink = std::back_inserter(text);
  fmt::format_to(sink, "{}\n(\n", cells.size());
  for (std::size_t p = 0; p < cells.size(); ++p) {
    fmt::format_to(sink, "({:.17g} {:.17g} {:.17g}) {}\n", xyz[3 * p], xyz[3 * p + 1],
                   xyz[3 * p + 2], cells[p]);
  }
  text += ")\n";
  cosim::write_file_atomically(file, text);
}

}  // namespace openfoam
