#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "swe/solver_2d.hpp"

// The SWE benchmarks' flow: a radial dam break over a bumpy bed with a dry
// corner, on a grid of nx x ny cells over [-1, 1] x [-1, -1 + 2 ny / nx].
namespace bench {

struct RadialDamBreak {
  swe::Grid2d grid;
  std::vector<double> bed, depth;  // of the cells [i_begin, i_end) x [j_begin, j_end), x fastest
};

// The whole grid, or the block of it given by the cell ranges.
inline RadialDamBreak radial_dam_break(int nx, int ny, int i_begin = 0, int i_end = -1,
                                       int j_begin = 0, int j_end = -1) {
  RadialDamBreak d;
  d.grid = {{-1.0, -1.0}, {2.0 / nx, 2.0 / nx}, {nx, ny}};
  if (i_end < 0) i_end = nx;
  if (j_end < 0) j_end = ny;
  for (int j = j_begin; j < j_end; ++j) {
    for (int i = i_begin; i < i_end; ++i) {
      const double x = -1.0 + (i + 0.5) * d.grid.spacing[0],
                   y = -1.0 + (j + 0.5) * d.grid.spacing[1];
      const double bed =
          0.1 * std::sin(4.0 * x) * std::cos(3.0 * y) + (x + y > 1.2 ? 0.8 * (x + y - 1.2) : 0.0);
      const double surface = x * x + y * y < 0.09 ? 1.0 : 0.5;
      d.bed.push_back(bed);
      d.depth.push_back(std::max(0.0, surface - bed));
    }
  }
  return d;
}

}  // namespace bench
