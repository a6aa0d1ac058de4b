#include "ice/diffusion/diffusion.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace ice {

namespace {

double harmonic_mean(double a, double b) {
  return a + b > 0.0 ? 2.0 * a * b / (a + b) : 0.0;
}

void require(bool condition, const char* what) {
  if (!condition) throw std::invalid_argument(std::string("Diffusion: ") + what);
}

}  // namespace

template <int Dim>
Diffusion<Dim>::Diffusion(const CellGrid<Dim>& grid,
                          const std::array<SideCondition, 2 * Dim>& sides)
    : grid_(grid), sides_(sides) {}

template <int Dim>
double Diffusion<Dim>::central_difference(const CellField& u, int cell, int direction) const {
  const int below = grid_.neighbour(cell, direction, -1);
  const int above = grid_.neighbour(cell, direction, +1);
  const int lo = below < 0 ? cell : below;
  const int hi = above < 0 ? cell : above;
  if (lo == hi) return 0.0;
  const double span = grid_.spacing()[direction] * ((below < 0 || above < 0) ? 1.0 : 2.0);
  return (u[at(hi)] - u[at(lo)]) / span;
}

template <int Dim>
void Diffusion<Dim>::add_viscous_momentum(std::span<const double> viscosity,
                                          std::span<const double> volume_fraction,
                                          const Velocity& velocity, double dt,
                                          Velocity& momentum) const {
  const auto cells = at(grid_.cell_count());
  require(viscosity.size() == cells && volume_fraction.size() == cells,
          "one viscosity and fraction per cell");
  for (int d = 0; d < Dim; ++d) {
    require(velocity[at(d)].size() == cells && momentum[at(d)].size() == cells,
            "one velocity per cell");
  }
  for (std::size_t c = 0; c < cells; ++c) require(viscosity[c] >= 0.0, "negative viscosity");
  for (int d = 0; d < Dim; ++d) {
    const double dx = grid_.spacing()[d];
    const double factor = dt / dx;  // flux * A / V = flux / dx
    for (int f = 0; f < grid_.face_count(d); ++f) {
      const int lower = grid_.lower_cell(d, f);
      const int upper = grid_.upper_cell(d, f);
      if (lower < 0 || upper < 0) continue;
      const double mu = harmonic_mean(volume_fraction[at(lower)] * viscosity[at(lower)],
                                      volume_fraction[at(upper)] * viscosity[at(upper)]);
      if (mu == 0.0) continue;
      // Face gradients: along the normal from the two cells, along the face
      // the mean of their central differences.
      std::array<std::array<double, 3>, 3> gradient{};  // gradient[i][j] = dU_i/dx_j
      for (int i = 0; i < Dim; ++i) {
        const CellField& u = velocity[at(i)];
        for (int j = 0; j < Dim; ++j) {
          gradient[at(i)][at(j)] =
              j == d ? (u[at(upper)] - u[at(lower)]) / dx
                     : 0.5 * (central_difference(u, lower, j) + central_difference(u, upper, j));
        }
      }
      double divergence = 0.0;
      for (int j = 0; j < Dim; ++j) divergence += gradient[at(j)][at(j)];
      for (int i = 0; i < Dim; ++i) {
        double stress = mu * (gradient[at(i)][at(d)] + gradient[at(d)][at(i)]);
        if (i == d) stress -= 2.0 / 3.0 * mu * divergence;
        momentum[at(i)][at(lower)] += factor * stress;
        momentum[at(i)][at(upper)] -= factor * stress;
      }
    }
  }
}

template <int Dim>
void Diffusion<Dim>::add_heat_conduction(std::span<const double> conductivity,
                                         std::span<const double> volume_fraction,
                                         std::span<const double> temperature, double dt,
                                         std::span<double> energy) const {
  const auto cells = at(grid_.cell_count());
  require(conductivity.size() == cells && volume_fraction.size() == cells &&
              temperature.size() == cells && energy.size() == cells,
          "one conductivity, fraction, temperature and energy per cell");
  for (std::size_t c = 0; c < cells; ++c) require(conductivity[c] >= 0.0, "negative conductivity");
  for (int d = 0; d < Dim; ++d) {
    const double dx = grid_.spacing()[d];
    for (int f = 0; f < grid_.face_count(d); ++f) {
      const int lower = grid_.lower_cell(d, f);
      const int upper = grid_.upper_cell(d, f);
      if (lower >= 0 && upper >= 0) {
        const double k = harmonic_mean(volume_fraction[at(lower)] * conductivity[at(lower)],
                                       volume_fraction[at(upper)] * conductivity[at(upper)]);
        const double flux = k * (temperature[at(upper)] - temperature[at(lower)]) / dx;
        energy[at(lower)] += dt * flux / dx;
        energy[at(upper)] -= dt * flux / dx;
        continue;
      }
      const bool upper_side = upper < 0;
      const int cell = upper_side ? lower : upper;
      const SideCondition& side = sides_[at(2 * d + (upper_side ? 1 : 0))];
      if (!side.temperature) continue;
      const double k = volume_fraction[at(cell)] * conductivity[at(cell)];
      energy[at(cell)] += dt * k * (*side.temperature - temperature[at(cell)]) / (0.5 * dx) / dx;
    }
  }
}

template <int Dim>
void smagorinsky_viscosity(const CellGrid<Dim>& grid,
                           const std::array<CellField, static_cast<std::size_t>(Dim)>& velocity,
                           std::span<const double> density, double constant,
                           std::span<double> viscosity) {
  const auto cells = at(grid.cell_count());
  require(density.size() == cells && viscosity.size() == cells,
          "one density and viscosity per cell");
  const double width = std::pow(grid.cell_volume(), 1.0 / Dim);
  for (int c = 0; c < grid.cell_count(); ++c) {
    std::array<std::array<double, 3>, 3> gradient{};
    for (int i = 0; i < Dim; ++i) {
      for (int j = 0; j < Dim; ++j) {
        const CellField& u = velocity[at(i)];
        const int below = grid.neighbour(c, j, -1);
        const int above = grid.neighbour(c, j, +1);
        const int lo = below < 0 ? c : below;
        const int hi = above < 0 ? c : above;
        const double span = grid.spacing()[j] * ((below < 0 || above < 0) ? 1.0 : 2.0);
        gradient[at(i)][at(j)] = lo == hi ? 0.0 : (u[at(hi)] - u[at(lo)]) / span;
      }
    }
    double ss = 0.0;  // S:S
    for (int i = 0; i < Dim; ++i) {
      for (int j = 0; j < Dim; ++j) {
        const double s = 0.5 * (gradient[at(i)][at(j)] + gradient[at(j)][at(i)]);
        ss += s * s;
      }
    }
    viscosity[at(c)] = density[at(c)] * constant * constant * width * width * std::sqrt(2.0 * ss);
  }
}

template <int Dim>
double diffusion_time_step(const CellGrid<Dim>& grid, double largest_diffusivity) {
  if (!(largest_diffusivity > 0.0)) return std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (int d = 0; d < Dim; ++d) sum += 1.0 / (grid.spacing()[d] * grid.spacing()[d]);
  return 1.0 / (2.0 * largest_diffusivity * sum);
}

template class Diffusion<1>;
template class Diffusion<2>;
template class Diffusion<3>;
template void smagorinsky_viscosity<1>(const CellGrid<1>&, const std::array<CellField, 1>&,
                                       std::span<const double>, double, std::span<double>);
template void smagorinsky_viscosity<2>(const CellGrid<2>&, const std::array<CellField, 2>&,
                                       std::span<const double>, double, std::span<double>);
template void smagorinsky_viscosity<3>(const CellGrid<3>&, const std::array<CellField, 3>&,
                                       std::span<const double>, double, std::span<double>);
template double diffusion_time_step<1>(const CellGrid<1>&, double);
template double diffusion_time_step<2>(const CellGrid<2>&, double);
template double diffusion_time_step<3>(const CellGrid<3>&, double);

}  // namespace ice
