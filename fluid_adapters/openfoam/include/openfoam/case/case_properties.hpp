#pragma once

#include <filesystem>

#include "openfoam/case/case_description.hpp"
#include "openfoam/foam/installation.hpp"

namespace openfoam {

// What the adapter needs of a case besides its cells: the plane a 2D case
// lies in, the two fluids and gravity. A generated case knows them from the
// YAML; a user's case is asked (its dictionaries through foamDictionary, its
// mesh through checkMesh).
struct CaseProperties {
  // 2: one cell thick along z between empty patches, declared to the
  // coupler per unit depth (volume / thickness) in x and y.
  int dimension = 3;
  double thickness = 1.0;  // [m] along z of a 2D case
  FluidProperties water;
  FluidProperties air;
  Vector3 gravity{};
  // OpenFOAM's hRef [m] (constant/hRef, 0 without): interFoam's
  // p = p_rgh + rho (g . x + |g| hRef).
  double reference_height = 0.0;

  // The volume of cell volume `v` as declared to the coupler: per unit depth in 2D.
  double declared_volume(double v) const { return dimension == 2 ? v / thickness : v; }
};

CaseProperties properties_of(const GeneratedCase& generated);

// A user's case in `case_dir` (meshed): transportProperties' water and air
// (rho, nu), constant/g, constant/hRef if there is one, and checkMesh's
// solution directions and bounding box. A missing entry throws
// cosim::InputError naming the file and entry; a 2D case whose empty
// direction is not z throws cosim::InputError too (the soil's plane is x-y).
CaseProperties read_case_properties(const Installation& installation,
                                    const std::filesystem::path& case_dir,
                                    const std::filesystem::path& log_dir);

}  // namespace openfoam
