#include "ice/case/make_solver.hpp"

#include <stdexcept>

#include "ice/solver/initial_state.hpp"

namespace ice {

namespace {

template <int Dim>
CellGrid<Dim> grid_of(const CaseDescription& c) {
  typename CellGrid<Dim>::Point origin, spacing;
  typename CellGrid<Dim>::CellIndex cells;
  for (int d = 0; d < Dim; ++d) {
    const auto k = static_cast<std::size_t>(d);
    origin[d] = c.origin[k];
    cells[k] = c.cells[k];
    spacing[d] = (c.upper[k] - c.origin[k]) / c.cells[k];
  }
  return CellGrid<Dim>(origin, spacing, cells);
}

// The case's initial state: fill, regions in order, then the pressure
// (given, or the discrete hydrostatic column of hydrostatic_pressure).
template <int Dim>
FluidState<Dim> initial_state(const CaseDescription& c, const CellGrid<Dim>& grid,
                              const Eigen::Matrix<double, Dim, 1>& gravity) {
  const InitialDescription& i = c.initial;
  const auto cells = static_cast<std::size_t>(grid.cell_count());
  CellFill<Dim> fill;
  fill.material.assign(cells, i.fill);
  fill.pressure.assign(cells, i.pressure.value_or(i.reference_pressure));
  fill.temperature.assign(cells, i.temperature);
  for (int d = 0; d < Dim; ++d) {
    fill.velocity[static_cast<std::size_t>(d)].assign(cells,
                                                      i.velocity[static_cast<std::size_t>(d)]);
  }
  for (int cell = 0; cell < grid.cell_count(); ++cell) {
    const auto centre = grid.cell_centre(cell);
    Vector3 x{};
    for (int d = 0; d < Dim; ++d) x[static_cast<std::size_t>(d)] = centre[d];
    const auto k = static_cast<std::size_t>(cell);
    for (const Region& r : i.regions) {
      if (!r.contains(x, Dim)) continue;
      fill.material[k] = r.material;
      if (r.pressure) fill.pressure[k] = *r.pressure;
      if (r.temperature) fill.temperature[k] = *r.temperature;
      if (r.velocity) {
        for (int d = 0; d < Dim; ++d) {
          fill.velocity[static_cast<std::size_t>(d)][k] =
              (*r.velocity)[static_cast<std::size_t>(d)];
        }
      }
    }
  }
  if (!i.pressure) {
    fill.pressure = hydrostatic_pressure(grid, c.materials, fill.material, fill.temperature,
                                         gravity, i.reference_pressure, i.minimum_volume_fraction);
  }
  return make_initial_state(grid, c.materials, fill, i.minimum_volume_fraction);
}

}  // namespace

template <int Dim>
std::unique_ptr<IceSolver<Dim>> make_solver(const CaseDescription& c) {
  if (c.dimension != Dim) throw std::invalid_argument("make_solver: the case's dimension differs");
  const CellGrid<Dim> grid = grid_of<Dim>(c);
  Eigen::Matrix<double, Dim, 1> gravity;
  for (int d = 0; d < Dim; ++d) gravity[d] = c.gravity[static_cast<std::size_t>(d)];
  typename IceSolver<Dim>::Sides sides;
  std::copy(c.sides.begin(), c.sides.end(), sides.begin());
  IceSolverOptions options;
  options.limiter = c.numerics.limiter;
  options.pressure = c.numerics.pressure;
  options.equilibration = c.numerics.equilibration;
  options.smagorinsky_constant = c.numerics.smagorinsky_constant;
  return std::make_unique<IceSolver<Dim>>(grid, c.materials, c.exchange, sides, gravity,
                                          initial_state<Dim>(c, grid, gravity), options);
}

template std::unique_ptr<IceSolver<1>> make_solver<1>(const CaseDescription&);
template std::unique_ptr<IceSolver<2>> make_solver<2>(const CaseDescription&);
template std::unique_ptr<IceSolver<3>> make_solver<3>(const CaseDescription&);

}  // namespace ice
