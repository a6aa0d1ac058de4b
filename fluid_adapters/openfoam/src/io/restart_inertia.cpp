#include "openfoam/io/restart_inertia.hpp"

#include <fmt/format.h>

#include "cosim/error.hpp"

namespace openfoam {

namespace {

// The solver's mixture density at time `name`: its rho file, or, at the
// start (not written yet), alpha rho_w + (1 - alpha) rho_a as it forms it.
std::vector<double> density_at(const CaseLayout& layout, const CaseProperties& properties,
                               const std::string& name) {
  if (layout.has(name, "rho")) return layout.read_scalar(name, "rho");
  std::vector<double> rho = layout.read_scalar(name, "alpha.water");
  for (double& a : rho) a = a * properties.water.density + (1.0 - a) * properties.air.density;
  return rho;
}

}  // namespace

std::vector<double> restart_fluid_fraction(std::span<const double> fluid_fraction,
                                           std::span<const double> density_before,
                                           std::span<const double> density_end) {
  if (density_before.size() != fluid_fraction.size() ||
      density_end.size() != fluid_fraction.size()) {
    throw cosim::Error(
        cosim::ExitCode::participant_failed,
        fmt::format("MPPICInterFoam's alphac and rho differ in length ({}, {} and "
                    "{} cells)",
                    fluid_fraction.size(), density_before.size(), density_end.size()));
  }
  std::vector<double> lagged(fluid_fraction.size());
  for (std::size_t c = 0; c < lagged.size(); ++c)
    lagged[c] = fluid_fraction[c] * density_before[c] / density_end[c];
  return lagged;
}

void write_restart_inertia(const CaseLayout& layout, const CaseProperties& properties,
                           const std::string& end, const std::string& before,
                           std::span<const double> fluid_fraction) {
  const std::vector<double> lagged = restart_fluid_fraction(
      fluid_fraction, density_at(layout, properties, before), density_at(layout, properties, end));
  layout.write_scalar_field(end, "alphac", "[0 0 0 0 0 0 0]", lagged);
}

}  // namespace openfoam
