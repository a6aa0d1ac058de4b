#include "mpm/case/velocity_history.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cosim/error.hpp"

namespace mpm {

namespace {

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

struct Cell {
  std::string_view text;
  int column = 1;  // 1-based
};

std::vector<Cell> split(std::string_view line) {
  std::vector<Cell> cells;
  std::size_t start = 0;
  for (;;) {
    const auto comma = line.find(',', start);
    const auto end = comma == std::string_view::npos ? line.size() : comma;
    cells.push_back({trimmed(line.substr(start, end - start)), static_cast<int>(start) + 1});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return cells;
}

}  // namespace

TimeSeries parse_velocity_history(std::string_view text, const std::filesystem::path& file,
                                  int dimension, const std::string& key_path) {
  const std::string name = file.string();
  auto fail = [&](int line, int column, const std::string& what) {
    throw cosim::InputError(cosim::SourceLocation{name, line, column}, key_path, what);
  };
  std::vector<std::string> expected{"time [s]", "vx [m/s]", "vy [m/s]"};
  if (dimension == 3) expected.emplace_back("vz [m/s]");

  TimeSeries series;
  std::istringstream in{std::string(text)};
  std::string line;
  int number = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++number;
    if (trimmed(line).empty()) continue;
    const auto cells = split(line);
    if (!header_seen) {
      std::vector<std::string> got;
      for (const auto& c : cells) got.emplace_back(c.text);
      if (got != expected)
        fail(number, 1,
             fmt::format("velocity history header must be '{}' for a {}D case, got '{}'",
                         fmt::join(expected, ","), dimension, trimmed(line)));
      header_seen = true;
      continue;
    }
    if (cells.size() != expected.size())
      fail(number, 1,
           fmt::format("expected {} values (time and {} velocity components), got {}",
                       expected.size(), dimension, cells.size()));
    double values[4] = {0, 0, 0, 0};
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const auto t = cells[c].text;
      const auto* end = t.data() + t.size();
      const auto [ptr, ec] = std::from_chars(t.data(), end, values[c]);
      if (ec != std::errc() || ptr != end || !std::isfinite(values[c]))
        fail(number, cells[c].column,
             fmt::format("'{}' in column '{}' is not a finite number", t, expected[c]));
    }
    if (!series.time.empty() && values[0] <= series.time.back())
      fail(number, 1,
           fmt::format("times must increase: {} s follows {} s", values[0], series.time.back()));
    series.time.push_back(values[0]);
    series.value.emplace_back(values[1], values[2], values[3]);
  }
  if (!header_seen) fail(0, 0, fmt::format("velocity history '{}' is empty", name));
  if (series.time.empty())
    fail(number, 0, fmt::format("velocity history '{}' has a header but no rows", name));
  return series;
}

TimeSeries read_velocity_history(const std::filesystem::path& file, int dimension,
                                 const cosim::config::Node& key) {
  std::ifstream in(file, std::ios::binary);
  if (!in) key.fail(fmt::format("cannot read velocity history '{}'", file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_velocity_history(text.str(), file, dimension, key.key_path());
}

}  // namespace mpm
