#pragma once

#include <array>
#include <filesystem>
#include <string>

namespace openfoam {

// system/decomposeParDict for `processes` subdomains by the simple method,
// `split` blocks along x, y, z (Debian's scotch decomposition is a stub).
std::string decompose_par_dict(int processes, const std::array<int, 3>& split);

void write_decompose_par_dict(const std::filesystem::path& case_dir, int processes,
                              const std::array<int, 3>& split);

}  // namespace openfoam
