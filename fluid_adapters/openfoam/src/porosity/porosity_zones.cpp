#include "openfoam/porosity/porosity_zones.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "openfoam/foam/foam_file_header.hpp"

namespace openfoam {

std::vector<PorosityZone> porosity_zones(std::span<const double> d, int zones) {
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (double v : d) {
    if (v <= 0.0) continue;
    smallest = std::min(smallest, v);
    largest = std::max(largest, v);
  }
  std::vector<PorosityZone> out;
  if (largest <= 0.0) return out;
  // Bin edges a hair outside the extremes, so every cell falls in one.
  const double lo = smallest * (1.0 - 1e-9), hi = largest * (1.0 + 1e-9);
  const int bins = largest / smallest < 1.0 + 1e-6 ? 1 : std::max(1, zones);
  const double ratio = std::pow(hi / lo, 1.0 / bins);
  for (int b = 0; b < bins; ++b) {
    const double lower = lo * std::pow(ratio, b);
    const double upper = b + 1 == bins ? hi : lo * std::pow(ratio, b + 1);
    // Only zones that hold a cell.
    double first = std::numeric_limits<double>::infinity(), last = 0.0;
    for (double v : d) {
      if (v >= lower && v < upper) {
        first = std::min(first, v);
        last = std::max(last, v);
      }
    }
    if (last > 0.0) out.push_back({lower, upper, std::sqrt(first * last)});
  }
  return out;
}

std::string topo_set_dict(const std::vector<PorosityZone>& zones) {
  std::string text = foam_file_header({"dictionary", "system", "topoSetDict"}) + "actions\n(\n";
  for (std::size_t z = 0; z < zones.size(); ++z) {
    text += fmt::format(
        "    {{\n        name soil{0};\n        type cellSet;\n        action new;\n"
        "        source fieldToCell;\n        field {1};\n        min {2:.17g};\n"
        "        max {3:.17g};\n    }}\n"
        "    {{\n        name soil{0};\n        type cellZoneSet;\n        action new;\n"
        "        source setToCellZone;\n        set soil{0};\n    }}\n",
        z, darcy_field, zones[z].lower, zones[z].upper);
  }
  return text + ");\n";
}

std::string porosity_fv_options(const std::vector<PorosityZone>& zones) {
  std::string text = foam_file_header({"dictionary", "constant", "fvOptions"});
  for (std::size_t z = 0; z < zones.size(); ++z) {
    const double d = zones[z].darcy;
    text += fmt::format(
        "soil{0}\n{{\n    type explicitPorositySource;\n    explicitPorositySourceCoeffs\n    {{\n"
        "        selectionMode cellZone;\n        cellZone soil{0};\n"
        "        type DarcyForchheimer;\n        d ({1:.17g} {1:.17g} {1:.17g});\n"
        "        f (0 0 0);\n        coordinateSystem\n        {{\n            origin (0 0 0);\n"
        "            rotation\n            {{\n                type none;\n            }}\n"
        "        }}\n    }}\n}}\n\n",
        z, d);
  }
  return text;
}

}  // namespace openfoam
