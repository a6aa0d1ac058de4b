#pragma once

#include <span>
#include <string>
#include <vector>

#include "openfoam/case/case_properties.hpp"
#include "openfoam/io/case_layout.hpp"

namespace openfoam {

// MPPICInterFoam's momentum equation takes its inertia from alphacRho =
// alphac rho, formed before each step's VOF update: a continuous run's
// ddt(alphacRho, U) - U ddt(alphacRho) weighs the step from t_n by
// alphac_n rho_(n-1), the density one step behind. A restart rebuilds that
// old alphacRho from the alphac and rho files of its start time, alphac_n
// rho_n, and where an interface crosses a cell within a step the two differ
// a thousandfold (water against air): restarted every step, a still tank
// with a 1 cm step in its surface reached 9 m/s within 0.05 s. The solver
// reads the alphac file only for that product (it takes alphac itself from
// its cloud), so writing
//
//   alphac_file = alphac_n rho_(n-1) / rho_n
//
// into the start directory gives a restart exactly the continuous run's
// inertia (checked against one continuous run: the same U to 3e-13 m/s).
std::vector<double> restart_fluid_fraction(std::span<const double> fluid_fraction,
                                           std::span<const double> density_before,
                                           std::span<const double> density_end);

// MPPICInterFoam's next start given the inertia of the step it would have
// taken next in one continuous run: restart_fluid_fraction into the alphac
// file of the end directory `end` from the densities there and at `before`,
// the time one step earlier.
void write_restart_inertia(const CaseLayout& layout, const CaseProperties& properties,
                           const std::string& end, const std::string& before,
                           std::span<const double> fluid_fraction);

}  // namespace openfoam
