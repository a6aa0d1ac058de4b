#pragma once

#include <filesystem>
#include <vector>

#include "openfoam/case/case_description.hpp"
#include "openfoam/case/case_properties.hpp"

namespace openfoam {

// The fields of the VOF solver at one time, per cell. MPPICInterFoam's U and
// alpha.water are per pore (fluid) volume: U is the interstitial velocity and
// the cell's water fraction is alphac alpha.water.
struct FoamFields {
  std::vector<double> alpha_water;
  std::vector<double> p_rgh;
  std::vector<double> p;         // [Pa]; at time 0 (not written yet) p_rgh + rho g.x
  std::vector<double> velocity;  // components as the mesh's dimension
  std::vector<double> alphac;    // the fluid fraction; empty: 1 (no cloud)
  // MPPICInterFoam: the momentum the cloud gave the fluid in the last step
  // (kinematicCloud:UTrans), components as the mesh's dimension; empty: none.
  std::vector<double> cloud_momentum;
};

// Reads alpha.water, p_rgh, U and, where present, p, alphac and
// kinematicCloud:UTrans from a time directory of `cells` cells.
FoamFields read_foam_fields(const std::filesystem::path& directory, std::size_t cells, int dim);

// The mixture's density and viscosity in cell c of fluids `water` and `air`.
double mixture_density(const FoamFields& f, std::size_t c, const FluidProperties& water,
                       const FluidProperties& air);
double mixture_viscosity(const FoamFields& f, std::size_t c, const FluidProperties& water,
                         const FluidProperties& air);

// p where it was not written yet (time 0): interFoam's
// p = p_rgh + rho (g . x + |g| hRef).
void complete_pressure(FoamFields& f, const std::vector<double>& centres,
                       const CaseProperties& properties);

}  // namespace openfoam
