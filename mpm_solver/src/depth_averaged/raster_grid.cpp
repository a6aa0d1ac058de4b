#include "mpm/depth_averaged/raster_grid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cosim/error.hpp"

namespace mpm {

RasterGrid::RasterGrid(int columns, int rows, Vec<2> first_centre, double cell_size,
                       std::vector<double> values_south_to_north)
    : columns_(columns),
      rows_(rows),
      first_centre_(std::move(first_centre)),
      cell_size_(cell_size),
      values_(std::move(values_south_to_north)) {
  if (columns_ < 1 || rows_ < 1)
    throw std::invalid_argument("a raster needs at least one column and one row");
  if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_))
    throw std::invalid_argument("a raster's cell size must be positive");
  if (values_.size() != static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_))
    throw std::invalid_argument(fmt::format("a {} x {} raster needs {} values, got {}", columns_,
                                            rows_, columns_ * rows_, values_.size()));
}

namespace {

// Reads whitespace-separated words with the line each starts on.
class Words {
 public:
  explicit Words(const std::filesystem::path& file) : file_(file), in_(file) {
    if (!in_) throw cosim::InputError({file.string(), 0, 0}, "", "cannot open the terrain raster");
  }
  bool next(std::string& word) {
    while (!(line_words_ >> word)) {
      std::string text;
      if (!std::getline(in_, text)) return false;
      ++line_;
      line_words_.clear();
      line_words_.str(text);
    }
    return true;
  }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    fail_at(line_, key, what);
  }
  [[noreturn]] void fail_at(int line, const std::string& key, const std::string& what) const {
    throw cosim::InputError({file_.string(), line, 0}, key, what);
  }
  int line() const { return line_; }
  double number(const std::string& word, const std::string& key) const {
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value))
      fail(key, fmt::format("'{}' is not a finite number", word));
    return value;
  }

 private:
  std::filesystem::path file_;
  std::ifstream in_;
  std::istringstream line_words_;
  int line_ = 0;
};

}  // namespace

RasterGrid RasterGrid::read_esri_ascii(const std::filesystem::path& file) {
  Words words(file);
  std::map<std::string, double> header;
  std::map<std::string, int> header_line;
  const std::vector<std::string> keys{"ncols",     "nrows",     "xllcorner", "yllcorner",
                                      "xllcenter", "yllcenter", "cellsize",  "nodata_value"};
  std::string word;
  // The header: key value pairs until the first number.
  while (words.next(word)) {
    std::string key = word;
    std::transform(key.begin(), key.end(), key.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      double number = 0.0;
      const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), number);
      if (error != std::errc() || end != word.data() + word.size())
        words.fail(word,
                   "unknown header key (ncols, nrows, xllcorner, yllcorner, xllcenter, "
                   "yllcenter, cellsize, NODATA_value)");
      break;
    }
    if (header.count(key)) words.fail(key, "given twice");
    std::string value;
    if (!words.next(value)) words.fail(key, "has no value");
    header[key] = words.number(value, key);
    header_line[key] = words.line();
    word.clear();
  }
  for (const char* key : {"ncols", "nrows", "cellsize"})
    if (!header.count(key)) words.fail(key, "missing from the header");
  const bool corner = header.count("xllcorner") && header.count("yllcorner");
  const bool centre = header.count("xllcenter") && header.count("yllcenter");
  if (corner == centre)
    words.fail_at(header_line.empty() ? words.line() : header_line.begin()->second, "xllcorner",
                  "give xllcorner and yllcorner, or xllcenter and yllcenter");
  const double ncols = header["ncols"], nrows = header["nrows"], size = header["cellsize"];
  if (ncols < 1 || nrows < 1 || ncols != std::floor(ncols) || nrows != std::floor(nrows))
    words.fail_at(header_line["ncols"], "ncols", "ncols and nrows must be positive integers");
  if (!(size > 0.0)) words.fail_at(header_line["cellsize"], "cellsize", "must be positive");
  const int columns = static_cast<int>(ncols), rows = static_cast<int>(nrows);
  Vec<2> first_centre;
  if (corner)
    first_centre = {header["xllcorner"] + 0.5 * size, header["yllcorner"] + 0.5 * size};
  else
    first_centre = {header["xllcenter"], header["yllcenter"]};
  const bool has_nodata = header.count("nodata_value") > 0;
  std::vector<double> values(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
  for (int r = rows - 1; r >= 0; --r) {  // the file lists the northern row first
    for (int c = 0; c < columns; ++c) {
      if (word.empty() && !words.next(word))
        words.fail("values", fmt::format("ends before row {} of {}, column {} of {}", rows - r,
                                         rows, c + 1, columns));
      const double value = words.number(word, "values");
      if (has_nodata && value == header["nodata_value"])
        words.fail("values", fmt::format("NODATA at row {}, column {}: the terrain must be "
                                         "complete",
                                         rows - r, c + 1));
      values[static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) +
             static_cast<std::size_t>(c)] = value;
      word.clear();
    }
  }
  if (words.next(word)) words.fail("values", "more values than ncols x nrows");
  return RasterGrid(columns, rows, first_centre, size, std::move(values));
}

RasterGrid::Patch RasterGrid::patch(const Vec<2>& x) const {
  Patch p{};
  const auto locate = [&](double s, int n, int& index, double& frac, bool& inside) {
    const double xi = s / cell_size_;
    inside = n > 1 && xi > 0.0 && xi < n - 1;
    const double clamped = std::clamp(xi, 0.0, static_cast<double>(std::max(n - 1, 0)));
    index = std::min(static_cast<int>(clamped), std::max(n - 2, 0));
    frac = n > 1 ? clamped - index : 0.0;
  };
  locate(x[0] - first_centre_[0], columns_, p.i, p.u, p.inside_x);
  locate(x[1] - first_centre_[1], rows_, p.j, p.v, p.inside_y);
  return p;
}

double RasterGrid::value(const Vec<2>& x) const {
  const Patch p = patch(x);
  const int i1 = std::min(p.i + 1, columns_ - 1), j1 = std::min(p.j + 1, rows_ - 1);
  const double south = (1.0 - p.u) * at(p.i, p.j) + p.u * at(i1, p.j);
  const double north = (1.0 - p.u) * at(p.i, j1) + p.u * at(i1, j1);
  return (1.0 - p.v) * south + p.v * north;
}

Vec<2> RasterGrid::gradient(const Vec<2>& x) const {
  const Patch p = patch(x);
  const int i1 = std::min(p.i + 1, columns_ - 1), j1 = std::min(p.j + 1, rows_ - 1);
  Vec<2> g = Vec<2>::Zero();
  if (p.inside_x)
    g[0] = ((1.0 - p.v) * (at(i1, p.j) - at(p.i, p.j)) + p.v * (at(i1, j1) - at(p.i, j1))) /
           cell_size_;
  if (p.inside_y)
    g[1] = ((1.0 - p.u) * (at(p.i, j1) - at(p.i, p.j)) + p.u * (at(i1, j1) - at(i1, p.j))) /
           cell_size_;
  return g;
}

}  // namespace mpm
