#include "cosim/io/csv_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

#include "cosim/error.hpp"

namespace cosim {

namespace {

constexpr std::string_view blanks = " \t\r";

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(blanks) - first + 1);
}

bool skipped(std::string_view line) {
  const std::string_view text = trimmed(line);
  return text.empty() || text.front() == '#';
}

// The cells of one line with the 1-based column each starts at.
std::vector<CsvTable::Cell> split(std::string_view line) {
  std::vector<CsvTable::Cell> cells;
  std::string text;
  std::size_t start = 0;
  bool quoted = false;
  bool was_quoted = false;
  auto finish = [&](std::size_t end) {
    const std::string_view raw = line.substr(start, end - start);
    const auto lead = raw.find_first_not_of(blanks);
    const int column = static_cast<int>(start + (lead == std::string_view::npos ? 0 : lead)) + 1;
    cells.push_back({was_quoted ? text : std::string(trimmed(text)), column});
    text.clear();
    was_quoted = false;
    start = end + 1;
  };
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        text += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        text += c;
      }
    } else if (c == '"') {
      quoted = was_quoted = true;
    } else if (c == ',') {
      finish(i);
    } else {
      text += c;
    }
  }
  finish(line.size());
  return cells;
}

// The whole text as a number (a leading '+' allowed), NaN otherwise.
double number_or_nan(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return value;
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& file, std::string key_path) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError(SourceLocation{file.string(), 0, 0}, key_path,
                     fmt::format("cannot read the CSV file {}", file.string()));
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), file, std::move(key_path));
}

CsvTable CsvTable::parse(std::string_view text, std::filesystem::path file, std::string key_path) {
  CsvTable table;
  table.file_ = std::move(file);
  table.key_path_ = std::move(key_path);
  int line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    const auto newline = text.find('\n', start);
    const std::size_t end = newline == std::string_view::npos ? text.size() : newline;
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (skipped(line)) continue;
    if (table.header_line_ == 0) {
      table.header_line_ = line_number;
      table.header_cells_ = split(line);
      for (const Cell& cell : table.header_cells_) table.header_.push_back(cell.text);
      continue;
    }
    Row row;
    row.line = line_number;
    row.cells = split(line);
    row.numbers.resize(table.header_.size(), std::numeric_limits<double>::quiet_NaN());
    row.texts.resize(table.header_.size());
    for (std::size_t c = 0; c < std::min(row.cells.size(), table.header_.size()); ++c) {
      row.numbers[c] = number_or_nan(row.cells[c].text);
      row.texts[c] = row.cells[c].text;
    }
    table.rows_.push_back(std::move(row));
  }
  if (table.header_line_ == 0)
    table.fail(0, 0, "no header row (the file is empty or only comments)");
  return table;
}

double CsvTable::number(std::size_t r, std::size_t c) const {
  const Row& row = rows_[r];
  const double value = row.numbers[c];
  if (!std::isfinite(value)) {
    fail(row.line, row.cells[c].column,
         fmt::format("'{}' in column '{}' is not a finite number", row.cells[c].text, header_[c]));
  }
  return value;
}

void CsvTable::fail(int line, int column, const std::string& what) const {
  throw InputError(SourceLocation{file_.string(), line, column}, key_path_, what);
}

bool CsvTable::has(const std::string& column) const {
  return std::find(header_.begin(), header_.end(), column) != header_.end();
}

std::size_t CsvTable::index(const std::string& column) const {
  const auto it = std::find(header_.begin(), header_.end(), column);
  if (it == header_.end()) {
    fail(header_line_, 1,
         fmt::format("no column '{}' (it has: {})", column, fmt::join(header_, ", ")));
  }
  return static_cast<std::size_t>(it - header_.begin());
}

std::vector<double> CsvTable::column(const std::string& name) const {
  const std::size_t c = index(name);
  std::vector<double> values;
  values.reserve(rows_.size());
  for (const Row& row : rows_) values.push_back(row.numbers[c]);
  return values;
}

}  // namespace cosim
