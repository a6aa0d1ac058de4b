#pragma once

#include <filesystem>
#include <vector>

#include "mpm/core/tensor.hpp"

namespace mpm {

// A terrain raster: values at the centres of square cells, x east, y north,
// as an ESRI ASCII grid stores them (ncols, nrows, xllcorner or xllcenter,
// yllcorner or yllcenter, cellsize, optional NODATA_value, then the rows
// from north to south). Read between the centres bilinearly; outside the
// outermost centres the edge values continue.
class RasterGrid {
 public:
  RasterGrid(int columns, int rows, Vec<2> first_centre, double cell_size,
             std::vector<double> values_south_to_north);

  // Throws cosim::InputError naming the file and line of what is wrong
  // (a missing or unknown header key, a non-number, a NODATA or missing value).
  static RasterGrid read_esri_ascii(const std::filesystem::path& file);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double cell_size() const { return cell_size_; }
  // Centre of the south-west cell.
  const Vec<2>& first_centre() const { return first_centre_; }
  // Row 0 is the southern one.
  double at(int column, int row) const {
    return values_[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
                   static_cast<std::size_t>(column)];
  }

  double value(const Vec<2>& x) const;
  // The gradient of the bilinear interpolant (zero across a clamped direction).
  Vec<2> gradient(const Vec<2>& x) const;

 private:
  struct Patch {
    int i, j;     // south-west centre of the patch
    double u, v;  // position inside it in [0, 1]
    bool inside_x, inside_y;
  };
  Patch patch(const Vec<2>& x) const;

  int columns_;
  int rows_;
  Vec<2> first_centre_;
  double cell_size_;
  std::vector<double> values_;
};

}  // namespace mpm
