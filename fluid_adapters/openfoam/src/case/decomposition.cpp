#include "openfoam/case/decomposition.hpp"

#include <fmt/format.h>

#include "cosim/io/files.hpp"
#include "openfoam/foam/foam_file_header.hpp"

namespace openfoam {

std::string decompose_par_dict(int processes, const std::array<int, 3>& split) {
  return foam_file_header({"dictionary", "system", "decomposeParDict"}) +
         fmt::format(
             "numberOfSubdomains {};\n\nmethod simple;\n\nsimpleCoeffs\n{{\n    n ({} {} {});\n"
             "    delta 0.001;\n}}\n",
             processes, split[0], split[1], split[2]);
}

void write_decompose_par_dict(const std::filesystem::path& case_dir, int processes,
                              const std::array<int, 3>& split) {
  cosim::write_file_atomically(case_dir / "system" / "decomposeParDict",
                               decompose_par_dict(processes, split));
}

}  // namespace openfoam
