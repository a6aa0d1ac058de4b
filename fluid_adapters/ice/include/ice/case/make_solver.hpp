#pragma once

#include <memory>

#include "ice/case/case_description.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {

// The solver a case describes, in its initial state: the fill, the regions
// in order, then the pressure (given, or the discrete hydrostatic column of
// hydrostatic_pressure). Dim must equal description.dimension
// (std::invalid_argument otherwise).
template <int Dim>
std::unique_ptr<IceSolver<Dim>> make_solver(const CaseDescription& description);

}  // namespace ice
