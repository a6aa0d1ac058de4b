#pragma once

#include <memory>
#include <utility>

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
// The same fill of the box of `count` cells from cell `first` of `grid` alone
// (x fastest): each cell as above, its centre the whole grid's; the box must
// span the grid along gravity when the pressure is hydrostatic (see
// fill_box_along_gravity), so that its columns are whole. A rank of a
// decomposed run fills its block so, not the whole grid.
template <int Dim>
CellFill<Dim> case_fill(const CaseDescription& description, const CellGrid<Dim>& grid,
                        const typename CellGrid<Dim>::CellIndex& first,
                        const typename CellGrid<Dim>::CellIndex& count);
// The box to fill for the block of `count` cells from `first`: the block,
// widened to the whole grid along gravity when the pressure is hydrostatic.
template <int Dim>
std::pair<typename CellGrid<Dim>::CellIndex, typename CellGrid<Dim>::CellIndex>
fill_box_along_gravity(const CaseDescription& description, const CellGrid<Dim>& grid,
                       const typename CellGrid<Dim>::CellIndex& first,
                       const typename CellGrid<Dim>::CellIndex& count);

}  // namespace ice
