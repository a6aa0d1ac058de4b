#include "openfoam/io/restart_inertia.hpp"

#include <fmt/format.h>

#include "cosim/error.hpp"

namespace openfoam {

std::vector<double> restart_fluid_fraction(std::span<const double> fluid_fraction,
                                           std::span<const double> density_before,
                                           std::span<const double> density_end) {
  if (density_before.size() != fluid_fraction.size() ||
      density_end.size() != fluid_fraction.size()) {
    throw cosim::Error(cosim::ExitCode::participant_failed,
                       fmt::format("MPPICInterFoam's alphac and rho differ in length ({}, {} and "
                                   "{} cells)",
                                   fluid_fraction.size(), density_before.size(),
                                   density_end.size()));
  }
  std::vector<double> lagged(fluid_fraction.size());
  for (std::size_t c = 0; c < lagged.size(); ++c)
    lagged[c] = fluid_fraction[c] * density_before[c] / density_end[c];
  return lagged;
}

}  // namespace openfoam
