#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace openfoam {

// system/decomposeParDict for `processes` subdomains by the simple method,
// `split` blocks along x, y, z (Debian's scotch decomposition is a stub).
std::string decompose_par_dict(int processes, const std::array<int, 3>& split);

// The blocks per direction of the simple method for `processes` subdomains
// of a mesh of `cells` cells whose centres are `centres` (x, y, z per cell):
// of the splits whose product is `processes` and that give every block at
// least one layer of cells (the distinct centre coordinates along each
// direction), the one that cuts the fewest cell faces, counted as if the
// cells were a grid of those layers (more blocks along x first on a tie).
// Throws cosim::InputError when no split fits.
std::array<int, 3> choose_split(int processes, const std::vector<double>& centres);

void write_decompose_par_dict(const std::filesystem::path& case_dir, int processes,
                              const std::array<int, 3>& split);

}  // namespace openfoam
