#include "ice/solver/initial_state.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "cosim/error.hpp"

namespace ice {

namespace {

void check_fraction(double minimum_volume_fraction, std::size_t materials) {
  if (!(minimum_volume_fraction >= 0.0) ||
      !(minimum_volume_fraction * static_cast<double>(materials) < 1.0)) {
    throw std::invalid_argument(
        fmt::format("initial state: minimum volume fraction {} must lie in [0, 1/{})",
                    minimum_volume_fraction, materials));
  }
}

double fraction_of(std::size_t material, int fill, std::size_t materials, double minimum) {
  return static_cast<int>(material) == fill ? 1.0 - static_cast<double>(materials - 1) * minimum
                                            : minimum;
}

double material_density(const FluidMaterial& material, double pressure, double temperature,
                        std::size_t cell) {
  const double rho = material.eos->density(pressure, temperature);
  if (!(rho > 0.0) || !std::isfinite(rho)) {
    throw cosim::NumericalError(fmt::format(
        "initial state: material '{}' has no state at {} Pa and {} K (cell {}): density {}",
        material.name, pressure, temperature, cell, rho));
  }
  return rho;
}

double mixture_density(const std::vector<FluidMaterial>& materials, int fill, double pressure,
                       double temperature, double minimum, std::size_t cell) {
  double rho = 0.0;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    rho += fraction_of(m, fill, materials.size(), minimum) *
           material_density(materials[m], pressure, temperature, cell);
  }
  return rho;
}

}  // namespace

template <int Dim>
FluidState<Dim> make_initial_state(const CellGrid<Dim>& grid,
                                   const std::vector<FluidMaterial>& materials,
                                   const CellFill<Dim>& fill, double minimum_volume_fraction) {
  const std::size_t n = materials.size();
  const std::size_t cells = at(grid.cell_count());
  check_fraction(minimum_volume_fraction, n);
  bool sizes = fill.material.size() == cells && fill.pressure.size() == cells &&
               fill.temperature.size() == cells;
  for (const auto& component : fill.velocity) sizes = sizes && component.size() == cells;
  if (!sizes) throw std::invalid_argument("initial state: the fill needs one value per cell");

  FluidState<Dim> state;
  state.pressure = fill.pressure;
  state.porosity.assign(cells, 1.0);
  for (auto& component : state.solid_velocity) component.assign(cells, 0.0);
  state.materials.resize(n);
  for (std::size_t m = 0; m < n; ++m) {
    MaterialState<Dim>& material = state.materials[m];
    material.bulk_density.resize(cells);
    material.temperature = fill.temperature;
    material.velocity = fill.velocity;
  }
  for (std::size_t c = 0; c < cells; ++c) {
    const int filling = fill.material[c];
    if (filling < 0 || at(filling) >= n) {
      throw std::invalid_argument(
          fmt::format("initial state: cell {} names material {} of {}", c, filling, n));
    }
    for (std::size_t m = 0; m < n; ++m) {
      state.materials[m].bulk_density[c] =
          fraction_of(m, filling, n, minimum_volume_fraction) *
          material_density(materials[m], fill.pressure[c], fill.temperature[c], c);
    }
  }
  return state;
}

template <int Dim>
CellField hydrostatic_pressure(const CellGrid<Dim>& grid,
                               const std::vector<FluidMaterial>& materials,
                               const std::vector<int>& fill_material, const CellField& temperature,
                               const Eigen::Matrix<double, Dim, 1>& gravity, double top_pressure,
                               double minimum_volume_fraction) {
  const std::size_t cells = at(grid.cell_count());
  check_fraction(minimum_volume_fraction, materials.size());
  if (fill_material.size() != cells || temperature.size() != cells) {
    throw std::invalid_argument("hydrostatic pressure: one fill and temperature per cell");
  }
  int axis = -1;
  for (int d = 0; d < Dim; ++d) {
    if (gravity[d] == 0.0) continue;
    if (axis >= 0) {
      throw std::invalid_argument(
          "hydrostatic pressure: gravity must lie along one grid direction");
    }
    axis = d;
  }
  CellField pressure(cells, top_pressure);
  if (axis < 0) return pressure;

  const double g = std::abs(gravity[axis]);
  const double dx = grid.spacing()[axis];
  const int length = grid.cells()[at(axis)];
  // Gravity towards -axis: the top is the upper side, marching downwards.
  const bool downwards = gravity[axis] < 0.0;
  const int step = downwards ? -1 : 1;
  const auto density = [&](int cell) {
    return mixture_density(materials, fill_material[at(cell)], pressure[at(cell)],
                           temperature[at(cell)], minimum_volume_fraction, at(cell));
  };
  for (int c = 0; c < grid.cell_count(); ++c) {
    auto ijk = grid.cell_ijk(c);
    if (ijk[at(axis)] != (downwards ? length - 1 : 0)) continue;
    for (int sweep = 0; sweep < 4; ++sweep) {
      auto here = ijk;
      int previous = -1;
      for (int k = 0; k < length; ++k) {
        const int cell = grid.cell(here);
        pressure[at(cell)] = previous < 0 ? top_pressure + 0.5 * g * dx * density(cell)
                                          : pressure[at(previous)] +
                                                0.5 * g * dx * (density(previous) + density(cell));
        previous = cell;
        here[at(axis)] += step;
      }
    }
  }
  return pressure;
}

#define ICE_INITIAL_STATE(Dim)                                                                \
  template FluidState<Dim> make_initial_state<Dim>(                                           \
      const CellGrid<Dim>&, const std::vector<FluidMaterial>&, const CellFill<Dim>&, double); \
  template CellField hydrostatic_pressure<Dim>(                                               \
      const CellGrid<Dim>&, const std::vector<FluidMaterial>&, const std::vector<int>&,       \
      const CellField&, const Eigen::Matrix<double, Dim, 1>&, double, double);
ICE_INITIAL_STATE(1)
ICE_INITIAL_STATE(2)
ICE_INITIAL_STATE(3)
#undef ICE_INITIAL_STATE

}  // namespace ice
