#include "bench/csv_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "cosim/error.hpp"

namespace cosim::bench {

namespace {

std::string trimmed(const std::string& cell) {
  const auto first = cell.find_first_not_of(" \t\r");
  const auto last = cell.find_last_not_of(" \t\r");
  return first == std::string::npos ? "" : cell.substr(first, last - first + 1);
}

// The cells of one line: a cell in double quotes may hold commas, and "" is a
// quote within it (RFC 4180, as results.csv writes them).
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
    } else if (c == '"') {
      quoted = was_quoted = true;
    } else if (c == ',') {
      cells.push_back(was_quoted ? cell : trimmed(cell));
      cell.clear();
      was_quoted = false;
    } else {
      cell += c;
    }
  }
  cells.push_back(was_quoted ? cell : trimmed(cell));
  return cells;
}

double number(const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    return used == text.size() ? v : std::numeric_limits<double>::quiet_NaN();
  } catch (const std::exception&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error(ExitCode::bad_input, fmt::format("cannot read {}", file.string()));
  CsvTable t;
  t.file_ = file;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line == "\r") continue;
    if (t.header_.empty()) {
      t.header_ = split(line);
      continue;
    }
    std::vector<std::string> cells = split(line);
    cells.resize(t.header_.size());
    std::vector<double> row;
    for (const auto& cell : cells) row.push_back(number(cell));
    t.rows_.push_back(std::move(row));
    t.text_.push_back(std::move(cells));
  }
  if (t.header_.empty())
    throw Error(ExitCode::bad_input, fmt::format("{}: no header row", file.string()));
  return t;
}

bool CsvTable::has(const std::string& column) const {
  return std::find(header_.begin(), header_.end(), column) != header_.end();
}

std::size_t CsvTable::index(const std::string& column) const {
  const auto it = std::find(header_.begin(), header_.end(), column);
  if (it == header_.end()) {
    throw Error(ExitCode::bad_input, fmt::format("{}: no column '{}' (it has: {})", file_.string(),
                                                 column, fmt::join(header_, ", ")));
  }
  return static_cast<std::size_t>(it - header_.begin());
}

std::vector<double> CsvTable::column(const std::string& name) const {
  const std::size_t c = index(name);
  std::vector<double> out;
  out.reserve(rows_.size());
  for (const auto& r : rows_) out.push_back(r[c]);
  return out;
}

}  // namespace cosim::bench
