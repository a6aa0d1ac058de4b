#include "openfoam/io/foam_fields.hpp"

#include <algorithm>
#include <cmath>

#include "openfoam/foam/field_file.hpp"

namespace openfoam {

namespace fs = std::filesystem;

namespace {

// The first `dim` components of a vector field.
std::vector<double> planar(const std::vector<double>& xyz, std::size_t cells, std::size_t dim) {
  std::vector<double> v(cells * dim);
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t d = 0; d < dim; ++d) v[c * dim + d] = xyz[3 * c + d];
  }
  return v;
}

}  // namespace

FoamFields read_foam_fields(const fs::path& directory, std::size_t cells, int dim) {
  const auto components = static_cast<std::size_t>(dim);
  FoamFields f;
  f.alpha_water = read_internal_field(directory / "alpha.water", FieldType::scalar, cells);
  f.p_rgh = read_internal_field(directory / "p_rgh", FieldType::scalar, cells);
  if (fs::exists(directory / "p"))
    f.p = read_internal_field(directory / "p", FieldType::scalar, cells);
  f.velocity =
      planar(read_internal_field(directory / "U", FieldType::vector, cells), cells, components);
  if (fs::exists(directory / "alphac"))
    f.alphac = read_internal_field(directory / "alphac", FieldType::scalar, cells);
  if (const fs::path trans = directory / "kinematicCloud:UTrans"; fs::exists(trans))
    f.cloud_momentum =
        planar(read_internal_field(trans, FieldType::vector, cells), cells, components);
  return f;
}

double mixture_density(const FoamFields& f, std::size_t c, const FluidProperties& water,
                       const FluidProperties& air) {
  // MULES lets alpha.water stray from [0, 1] by a little.
  const double a = std::clamp(f.alpha_water[c], 0.0, 1.0);
  return a * water.density + (1.0 - a) * air.density;
}

double mixture_viscosity(const FoamFields& f, std::size_t c, const FluidProperties& water,
                         const FluidProperties& air) {
  const double a = std::clamp(f.alpha_water[c], 0.0, 1.0);
  return a * water.viscosity + (1.0 - a) * air.viscosity;
}

void complete_pressure(FoamFields& f, const std::vector<double>& centres,
                       const CaseProperties& properties) {
  if (!f.p.empty()) return;
  const Vector3& g = properties.gravity;
  const double gh_reference =
      std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) * properties.reference_height;
  f.p.resize(f.p_rgh.size());
  for (std::size_t c = 0; c < f.p.size(); ++c) {
    const double gh = g[0] * centres[3 * c] + g[1] * centres[3 * c + 1] +
                      g[2] * centres[3 * c + 2] + gh_reference;
    f.p[c] = f.p_rgh[c] + mixture_density(f, c, properties.water, properties.air) * gh;
  }
}

}  // namespace openfoam
