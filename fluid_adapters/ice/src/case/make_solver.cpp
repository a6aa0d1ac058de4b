#include "ice/case/make_solver.hpp"

#include <stdexcept>

#include "ice/solver/initial_state.hpp"

namespace ice {

template <int Dim>
CellGrid<Dim> case_grid(const CaseDescription& c) {
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

template <int Dim>
Eigen::Matrix<double, Dim, 1> case_gravity(const CaseDescription& c) {
  Eigen::Matrix<double, Dim, 1> gravity;
  for (int d = 0; d < Dim; ++d) gravity[d] = c.gravity[static_cast<std::size_t>(d)];
  return gravity;
}

template <int Dim>
CellFill<Dim> case_fill(const CaseDescription& c, const CellGrid<Dim>& grid) {
  return case_fill<Dim>(c, grid, {}, grid.cells());
}

template <int Dim>
CellFill<Dim> case_fill(const CaseDescription& c, const CellGrid<Dim>& grid,
                        const typename CellGrid<Dim>::CellIndex& first,
                        const typename CellGrid<Dim>::CellIndex& count) {
  const InitialDescription& i = c.initial;
  const Eigen::Matrix<double, Dim, 1> gravity = case_gravity<Dim>(c);
  const CellGrid<Dim> box(grid.origin(), grid.spacing(), count);
  const auto cells = static_cast<std::size_t>(box.cell_count());
  CellFill<Dim> fill;
  fill.material.assign(cells, i.fill);
  fill.pressure.assign(cells, i.pressure.value_or(i.reference_pressure));
  fill.temperature.assign(cells, i.temperature);
  for (int d = 0; d < Dim; ++d) {
    fill.velocity[static_cast<std::size_t>(d)].assign(cells,
                                                      i.velocity[static_cast<std::size_t>(d)]);
  }
  for (int cell = 0; cell < box.cell_count(); ++cell) {
    auto ijk = box.cell_ijk(cell);
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) ijk[d] += first[d];
    const auto centre = grid.cell_centre(grid.cell(ijk));
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
    fill.pressure = hydrostatic_pressure(box, c.materials, fill.material, fill.temperature, gravity,
                                         i.reference_pressure, i.minimum_volume_fraction);
  }
  return fill;
}

template <int Dim>
std::pair<typename CellGrid<Dim>::CellIndex, typename CellGrid<Dim>::CellIndex>
fill_box_along_gravity(const CaseDescription& c, const CellGrid<Dim>& grid,
                       const typename CellGrid<Dim>::CellIndex& first,
                       const typename CellGrid<Dim>::CellIndex& count) {
  auto box = std::pair{first, count};
  if (c.initial.pressure) return box;
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    if (c.gravity[d] == 0.0) continue;
    box.first[d] = 0;
    box.second[d] = grid.cells()[d];
  }
  return box;
}

IceSolverOptions case_solver_options(const CaseDescription& c) {
  IceSolverOptions options;
  options.limiter = c.numerics.limiter;
  options.pressure = c.numerics.pressure;
  options.equilibration = c.numerics.equilibration;
  options.smagorinsky_constant = c.numerics.smagorinsky_constant;
  return options;
}

template <int Dim>
typename IceSolver<Dim>::Sides case_sides(const CaseDescription& c) {
  typename IceSolver<Dim>::Sides sides;
  std::copy_n(c.sides.begin(), sides.size(), sides.begin());
  return sides;
}

template <int Dim>
std::unique_ptr<IceSolver<Dim>> make_solver(const CaseDescription& c) {
  if (c.dimension != Dim) throw std::invalid_argument("make_solver: the case's dimension differs");
  const CellGrid<Dim> grid = case_grid<Dim>(c);
  return std::make_unique<IceSolver<Dim>>(
      grid, c.materials, c.exchange, case_sides<Dim>(c), case_gravity<Dim>(c),
      make_initial_state(grid, c.materials, case_fill<Dim>(c, grid),
                         c.initial.minimum_volume_fraction),
      case_solver_options(c));
}

#define ICE_INSTANTIATE_CASE(D)                                                                    \
  template CellGrid<D> case_grid<D>(const CaseDescription&);                                       \
  template Eigen::Matrix<double, D, 1> case_gravity<D>(const CaseDescription&);                    \
  template CellFill<D> case_fill<D>(const CaseDescription&, const CellGrid<D>&);                   \
  template CellFill<D> case_fill<D>(const CaseDescription&, const CellGrid<D>&,                    \
                                    const CellGrid<D>::CellIndex&, const CellGrid<D>::CellIndex&); \
  template std::pair<CellGrid<D>::CellIndex, CellGrid<D>::CellIndex> fill_box_along_gravity<D>(    \
      const CaseDescription&, const CellGrid<D>&, const CellGrid<D>::CellIndex&,                   \
      const CellGrid<D>::CellIndex&);                                                              \
  template IceSolver<D>::Sides case_sides<D>(const CaseDescription&);                              \
  template std::unique_ptr<IceSolver<D>> make_solver<D>(const CaseDescription&);
ICE_INSTANTIATE_CASE(1)
ICE_INSTANTIATE_CASE(2)
ICE_INSTANTIATE_CASE(3)
#undef ICE_INSTANTIATE_CASE

}  // namespace ice
