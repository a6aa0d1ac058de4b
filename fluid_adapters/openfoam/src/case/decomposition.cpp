#include "openfoam/case/decomposition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "cosim/error.hpp"
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

namespace {

// The distinct cell-centre coordinates along each direction, to a
// millionth of the mesh's extent along it.
struct Layers {
  std::array<std::size_t, 3> count{};
};

Layers layers_of(const std::vector<double>& centres) {
  Layers layers;
  const std::size_t cells = centres.size() / 3;
  for (std::size_t d = 0; d < 3; ++d) {
    std::vector<double> x(cells);
    for (std::size_t i = 0; i < cells; ++i) x[i] = centres[3 * i + d];
    std::sort(x.begin(), x.end());
    if (x.empty()) continue;
    const double tolerance = 1e-6 * (x.back() - x.front());
    layers.count[d] = 1;
    for (std::size_t i = 1; i < x.size(); ++i)
      if (x[i] - x[i - 1] > tolerance) ++layers.count[d];
  }
  return layers;
}

}  // namespace

std::array<int, 3> choose_split(int processes, const std::vector<double>& centres) {
  const Layers layers = layers_of(centres);
  // A cut across direction d cuts the faces of one layer of cells normal
  // to d: the product of the other two directions' layers.
  const auto layer_area = [&](std::size_t d) {
    double area = 1.0;
    for (std::size_t e = 0; e < 3; ++e)
      if (e != d) area *= static_cast<double>(std::max<std::size_t>(layers.count[e], 1));
    return area;
  };
  std::optional<std::array<int, 3>> best;
  double best_cut = 0.0;
  for (int x = processes; x >= 1; --x) {
    if (processes % x != 0) continue;
    for (int y = processes / x; y >= 1; --y) {
      if ((processes / x) % y != 0) continue;
      const std::array<int, 3> split{x, y, processes / x / y};
      bool fits = true;
      double cut = 0.0;
      for (std::size_t d = 0; d < 3; ++d) {
        fits = fits && static_cast<std::size_t>(split[d]) <= layers.count[d];
        cut += (split[d] - 1) * layer_area(d);
      }
      if (fits && (!best || cut < best_cut)) {
        best = split;
        best_cut = cut;
      }
    }
  }
  if (!best)
    throw cosim::InputError(fmt::format(
        "OpenFOAM cannot run on {} processes: no split of the mesh's {} x {} x {} layers of cells "
        "into {} blocks gives every block a layer",
        processes, layers.count[0], layers.count[1], layers.count[2], processes));
  return *best;
}

void write_decompose_par_dict(const std::filesystem::path& case_dir, int processes,
                              const std::array<int, 3>& split) {
  cosim::write_file_atomically(case_dir / "system" / "decomposeParDict",
                               decompose_par_dict(processes, split));
}

}  // namespace openfoam
