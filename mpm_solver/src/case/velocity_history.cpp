#include "mpm/case/velocity_history.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "cosim/io/csv_table.hpp"

namespace mpm {

TimeSeries parse_velocity_history(std::string_view text, const std::filesystem::path& file,
                                  int dimension, const std::string& key_path) {
  const cosim::CsvTable table = cosim::CsvTable::parse(text, file, key_path);
  std::vector<std::string> expected{"time [s]", "vx [m/s]", "vy [m/s]"};
  if (dimension == 3) expected.emplace_back("vz [m/s]");
  if (table.header() != expected) {
    table.fail(table.header_line(), 1,
               fmt::format("velocity history header must be '{}' for a {}D case, got '{}'",
                           fmt::join(expected, ","), dimension, fmt::join(table.header(), ",")));
  }
  if (table.rows() == 0) {
    table.fail(table.last_line(), 0,
               fmt::format("velocity history '{}' has a header but no rows", file.string()));
  }
  TimeSeries series;
  for (std::size_t row = 0; row < table.rows(); ++row) {
    if (table.cells(row).size() != expected.size())
      table.fail(table.line(row), 1,
                 fmt::format("expected {} values (time and {} velocity components), got {}",
                             expected.size(), dimension, table.cells(row).size()));
    double values[4] = {0, 0, 0, 0};
    for (std::size_t c = 0; c < expected.size(); ++c) values[c] = table.number(row, c);
    if (!series.time.empty() && values[0] <= series.time.back())
      table.fail(
          table.line(row), 1,
          fmt::format("times must increase: {} s follows {} s", values[0], series.time.back()));
    series.time.push_back(values[0]);
    series.value.emplace_back(values[1], values[2], values[3]);
  }
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
