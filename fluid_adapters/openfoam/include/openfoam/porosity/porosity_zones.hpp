#pragma once

#include <span>
#include <string>
#include <vector>

// The fallback for rigid, slow porous structures: the soil as interFoam's
// explicitPorositySource (DarcyForchheimer) on cell zones that topoSet
// rebuilds each window from a field the adapter writes. Per unit volume the
// source gives the water -mu d U (U superficial: interFoam has no porosity
// in continuity or inertia, and no solid velocity in the drag). OpenFOAM
// takes one d per zone, so the cells' coefficients are binned into zones
// (log-spaced, each zone the geometric mean of its cells' range).
namespace openfoam {

struct PorosityZone {
  double lower = 0.0;  // the zone's cells have lower <= d < upper [1/m^2]
  double upper = 0.0;
  double darcy = 0.0;  // the zone's d [1/m^2]
};

// Zones for the cells' coefficients `d` (0: no soil): at most `zones`, one
// when all equal, none when no cell has soil. Two cells whose d differ by
// less than the bins' ratio share a zone.
std::vector<PorosityZone> porosity_zones(std::span<const double> d, int zones);

// The name of the field holding each cell's d, topoSet's source.
inline constexpr const char* darcy_field = "soilDarcyCoefficient";

// system/topoSetDict: per zone a cellSet by fieldToCell on darcy_field and
// the cellZone made from it (zones soil0, soil1, ...).
std::string topo_set_dict(const std::vector<PorosityZone>& zones);

// constant/fvOptions: an explicitPorositySource per zone, isotropic d, no
// Forchheimer term.
std::string porosity_fv_options(const std::vector<PorosityZone>& zones);

}  // namespace openfoam
