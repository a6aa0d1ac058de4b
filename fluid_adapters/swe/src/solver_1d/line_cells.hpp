#pragma once

#include <cstddef>
#include <vector>

namespace swe::solver_1d {

// Ghost cells on each side of the line; arrays of cell values hold them
// first and last, so cell i is at index i + ghost_layers.
inline constexpr std::size_t ghost_layers = 2;

// The widths the face and cell loops need, precomputed once from the edges.
// Ghost cells mirror the interior widths (the ghost next to the boundary has
// the width of the interior cell next to it, the outer one of the next).
struct LineCells {
  std::size_t count = 0;                    // interior cells n
  std::vector<double> half_width;           // n + 4, ghosts included
  std::vector<double> inv_width;            // n + 4
  std::vector<double> inv_centre_distance;  // n + 3: [k] = 1 / (x_c[k+1] - x_c[k])
  std::vector<double> inv_face_width;       // n + 1 faces: 1 / min(width left, width right)
};

// Throws cosim::InputError for fewer than two edges or edges that do not increase.
LineCells make_line_cells(const std::vector<double>& edges);

}  // namespace swe::solver_1d
