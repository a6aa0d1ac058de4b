#include "cosim/io/time_series_writer.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace cosim {
namespace {

using testing::read_text;
using testing::ScratchDirectory;

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

TEST(TimeSeriesWriter, HeaderAndRowsRoundTripAtFullPrecision) {
  ScratchDirectory dir;
  const std::vector<std::string> columns{column_name("time", "s"), column_name("eta_gauge1", "m"),
                                         "u_gauge1 [m/s]"};
  EXPECT_EQ(columns[0], "time [s]");
  const std::vector<std::vector<double>> rows{
      {0.0, 1.0 / 3.0, -2.5e17},
      {0.1, std::numbers::pi, 1e-300},
      {0.30000000000000004, std::nextafter(1.0, 2.0), std::numeric_limits<double>::denorm_min()}};
  {
    TimeSeriesWriter csv(dir / "gauges.csv", columns);
    for (const auto& row : rows) csv.append(row);
    EXPECT_EQ(csv.rows_written(), 3u);
  }
  const auto lines = split(read_text(dir / "gauges.csv"), '\n');
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "time [s],eta_gauge1 [m],u_gauge1 [m/s]");
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto cells = split(lines[r + 1], ',');
    ASSERT_EQ(cells.size(), 3u);
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_EQ(std::strtod(cells[c].c_str(), nullptr), rows[r][c]) << cells[c];
  }
}

TEST(TimeSeriesWriter, RowsSurviveAProcessThatDiesWithoutCleanup) {
  ScratchDirectory dir;
  const auto path = dir / "probe.csv";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    TimeSeriesWriter csv(path, {"time [s]", "p_probe [Pa]"});
    for (int i = 0; i < 100; ++i) csv.append({0.01 * i, 1e5 + i});
    std::_Exit(9);  // no destructors, no stdio flush
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 9);
  const auto lines = split(read_text(path), '\n');
  ASSERT_EQ(lines.size(), 101u);
  EXPECT_EQ(lines.back(), "0.98999999999999999,100099");
}

TEST(TimeSeriesWriter, AppendModeContinuesAMatchingFileAndRefusesAnotherHeader) {
  ScratchDirectory dir;
  const auto path = dir / "series.csv";
  { TimeSeriesWriter(path, {"time [s]", "x [m]"}).append({0.0, 1.0}); }
  {
    TimeSeriesWriter csv(path, {"time [s]", "x [m]"}, TimeSeriesWriter::Mode::append);
    csv.append({1.0, 2.0});
  }
  EXPECT_EQ(read_text(path), "time [s],x [m]\n0,1\n1,2\n");
  EXPECT_THROW(TimeSeriesWriter(path, {"time [s]", "y [m]"}, TimeSeriesWriter::Mode::append),
               InputError);
  EXPECT_EQ(read_text(path), "time [s],x [m]\n0,1\n1,2\n");
  { TimeSeriesWriter(path, {"time [s]"}); }
  EXPECT_EQ(read_text(path), "time [s]\n");
}

TEST(TimeSeriesWriter, RejectsBadColumnsAndRowsOfTheWrongLength) {
  ScratchDirectory dir;
  EXPECT_THROW(TimeSeriesWriter(dir / "a.csv", {"time [s]", "a,b"}), InputError);
  EXPECT_THROW(TimeSeriesWriter(dir / "a.csv", {}), InputError);
  TimeSeriesWriter csv(dir / "b.csv", {"time [s]", "x [m]"});
  EXPECT_THROW(csv.append({1.0}), InputError);
  EXPECT_EQ(read_text(dir / "b.csv"), "time [s],x [m]\n");
  EXPECT_THROW(TimeSeriesWriter(dir / "missing_dir" / "c.csv", {"t [s]"}), Error);
}

}  // namespace
}  // namespace cosim
