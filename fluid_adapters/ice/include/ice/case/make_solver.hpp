#pragma once

#include <memory>

#include "ice/case/case_description.hpp"
#include "ice/solver/ice_solver.hpp"
#include "ice/solver/initial_state.hpp"

namespace ice {

// The solver a case describes, in its initial state: the fill, the regions
// in order, then the pressure (given, or the discrete hydrostatic column of
// hydrostatic_pressure). Dim must equal description.dimension
// (std::invalid_argument otherwise).
template <int Dim>
std::unique_ptr<IceSolver<Dim>> make_solver(const CaseDescription& description);

// The parts make_solver puts together, for a solver of one block of the
// case's grid (ice/parallel): the whole grid, gravity, the sides, the
// solver's options and the initial fill of `grid` (the fill, the regions in
// order, then the pressure: given, or hydrostatic down each whole column).
template <int Dim>
CellGrid<Dim> case_grid(const CaseDescription& description);
template <int Dim>
Eigen::Matrix<double, Dim, 1> case_gravity(const CaseDescription& description);
template <int Dim>
typename IceSolver<Dim>::Sides case_sides(const CaseDescription& description);
IceSolverOptions case_solver_options(const CaseDescription& description);
template <int Dim>
CellFill<Dim> case_fill(const CaseDescription& description, const CellGrid<Dim>& grid);

}  // namespace ice
