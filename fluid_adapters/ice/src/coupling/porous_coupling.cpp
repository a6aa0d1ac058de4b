#include "ice/coupling/porous_coupling.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cosim/fields.hpp"
#include "ice/io/state_output.hpp"

namespace ice {

namespace {

namespace f = cosim::fields;

cosim::FieldSpec field(const f::Field& field, int dimension, double lower_bound = -INFINITY,
                       double upper_bound = INFINITY) {
  cosim::FieldSpec spec = field.on(PorousCoupling<1>::mesh_name, dimension);
  spec.lower_bound = lower_bound;
  spec.upper_bound = upper_bound;
  return spec;
}

}  // namespace

template <int Dim>
void PorousCoupling<Dim>::declare(
    cosim::Participant& participant, IceSolver<Dim>& solver,
    std::optional<std::pair<cosim::Mesh, cosim::MeshPart>> decomposed) {
  if (decomposed)
    participant.declare_mesh(std::move(decomposed->first), std::move(decomposed->second));
  else
    participant.declare_mesh(cell_mesh(solver.grid(), mesh_name));
  participant.declare_read(field(f::solid_fraction, Dim, 0.0, 1.0), 0.0);
  participant.declare_read(field(f::solid_velocity, Dim), 0.0);
  if (description_.drag_in_solver) {
    participant.declare_read(field(f::solid_bulk_density, Dim, 0.0), 0.0);
    participant.declare_read(field(f::drag_coefficient, Dim, 0.0), 0.0);
    participant.declare_write(field(f::momentum_exchange_impulse, Dim));
  } else {
    participant.declare_read(field(f::momentum_exchange_impulse, Dim), 0.0);
  }
  participant.declare_write(field(f::pore_pressure, Dim));
  participant.declare_write(field(f::pore_pressure_force, Dim));
  participant.declare_write(field(f::fluid_velocity, Dim));
  participant.declare_write(field(f::fluid_bulk_density, Dim, 0.0));
  participant.declare_write(field(f::pore_fluid_bulk_modulus, Dim, 0.0));
  if (description_.heat_exchange) {
    participant.declare_write(field(f::fluid_temperature, Dim));
    participant.declare_write(field(f::fluid_heat_capacity, Dim, 0.0));
    participant.declare_read(field(f::heat_exchange_energy, Dim), 0.0);
  }
  write_fields(participant, solver);
}

template <int Dim>
void PorousCoupling<Dim>::read_medium(const cosim::Participant& participant, IceSolver<Dim>& solver,
                                      bool first_window, double relative_time) {
  const auto cells = static_cast<std::size_t>(solver.grid().cell_count());
  const auto dim = static_cast<std::size_t>(Dim);
  buffer_.resize(cells * dim);
  porosity_.resize(cells);
  participant.read(f::solid_fraction.name, std::span<double>(buffer_.data(), cells), relative_time);
  for (std::size_t c = 0; c < cells; ++c)
    porosity_[c] = std::clamp(1.0 - buffer_[c], description_.minimum_porosity, 1.0);
  participant.read(f::solid_velocity.name, buffer_, relative_time);
  for (std::size_t d = 0; d < dim; ++d) {
    solid_velocity_[d].resize(cells);
    for (std::size_t c = 0; c < cells; ++c) solid_velocity_[d][c] = buffer_[c * dim + d];
  }
  if (description_.drag_in_solver) {
    drag_.resize(cells);
    solid_density_.resize(cells);
    participant.read(f::drag_coefficient.name, drag_, relative_time);
    participant.read(f::solid_bulk_density.name, solid_density_, relative_time);
  }
  solver.set_porous_medium(porosity_, solid_velocity_,
                           first_window ? PorosityChange::fill_pores : PorosityChange::displace);
  if (description_.drag_in_solver) {
    if (first_window) solver.set_drag_viscosity(description_.drag_viscosity);
    solver.set_solid_drag(drag_, solid_density_);
  }
  if (!warned_) {
    warned_ = true;
    const double limit = explicit_window_limit(solver);
    if (participant.window_size() > limit) {
      spdlog::warn(
          "ice coupling: the window {:.3g} s is longer than the {:.3g} s the pore water's pressure "
          "wave takes across an exchange cell holding solid; the explicit exchange of porosity "
          "and pore pressure may be unstable (architecture.md §3): use window <= {:.2g} s",
          participant.window_size(), limit, limit);
    }
  }
}

template <int Dim>
double PorousCoupling<Dim>::explicit_window_limit(const IceSolver<Dim>& solver) const {
  const FluidState<Dim>& state = solver.state();
  double spacing = std::numeric_limits<double>::infinity();
  for (int d = 0; d < Dim; ++d) spacing = std::min(spacing, solver.grid().spacing()[d]);
  double fastest = 0.0;
  for (std::size_t c = 0; c < state.porosity.size(); ++c) {
    if (state.porosity[c] >= 1.0) continue;
    // A held solid (the solid solver marks it with an immense bulk density)
    // does not answer the pressure: no feedback to resolve.
    if (!solid_density_.empty() && solid_density_[c] > held_solid_bulk_density) continue;
    // Undrained, the pores' fluids carry the load: the mixture's bulk
    // modulus is about 1 / sum_f phi_f kappa_f (the skeleton's stiffness is
    // far smaller) and its inertia the fluids' and, where known (drag: ice),
    // the solid's mass; the fluids' alone gives a faster, safe wave.
    double compressibility = 0.0, mass = 0.0;
    for (std::size_t m = 0; m < state.materials.size(); ++m) {
      const MaterialState<Dim>& material = state.materials[m];
      const EquationOfState& eos = *solver.materials()[m].eos;
      compressibility +=
          material.volume_fraction[c] *
          eos.adiabatic_compressibility(material.density[c], material.temperature[c]);
      mass += material.bulk_density[c];
    }
    if (!solid_density_.empty()) mass += solid_density_[c];
    if (compressibility > 0.0 && mass > 0.0)
      fastest = std::max(fastest, std::sqrt(1.0 / (compressibility * mass)));
  }
  return fastest > 0.0 ? spacing / fastest : std::numeric_limits<double>::infinity();
}

template <int Dim>
void PorousCoupling<Dim>::exchange_step(cosim::Participant& participant, double dt,
                                        IceSolver<Dim>& solver) {
  const std::size_t size =
      static_cast<std::size_t>(solver.grid().cell_count()) * static_cast<std::size_t>(Dim);
  if (description_.heat_exchange) {
    buffer_.resize(static_cast<std::size_t>(solver.grid().cell_count()));
    participant.read_increment(f::heat_exchange_energy.name, dt, buffer_);
    solver.add_heat(buffer_);
  }
  buffer_.resize(size);
  if (!description_.drag_in_solver) {
    participant.read_increment(f::momentum_exchange_impulse.name, dt, buffer_);
    solver.add_momentum(buffer_);
    return;
  }
  // The impulse is an integral field: its rate over this step.
  solver.take_solid_impulse(buffer_);
  for (double& j : buffer_) j /= dt;
  participant.write(f::momentum_exchange_impulse.name, buffer_);
}

template <int Dim>
void PorousCoupling<Dim>::write_fields(cosim::Participant& participant, IceSolver<Dim>& solver) {
  const FluidState<Dim>& state = solver.state();
  const std::size_t cells = state.pressure.size();
  const auto dim = static_cast<std::size_t>(Dim);
  density_.assign(cells, 0.0);
  velocity_.assign(cells * dim, 0.0);
  for (const MaterialState<Dim>& m : state.materials) {
    for (std::size_t c = 0; c < cells; ++c) {
      density_[c] += m.bulk_density[c];
      for (std::size_t d = 0; d < dim; ++d)
        velocity_[c * dim + d] += m.bulk_density[c] * m.velocity[d][c];
    }
  }
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t d = 0; d < dim; ++d) velocity_[c * dim + d] /= density_[c];
  }
  participant.write(f::pore_pressure.name, state.pressure);
  force_.resize(cells * dim);
  solver.solid_pressure_force(force_);
  participant.write(f::pore_pressure_force.name, force_);
  participant.write(f::fluid_velocity.name, velocity_);
  participant.write(f::fluid_bulk_density.name, density_);
  // The pores' fluids in series: 1 / K_f = sum_m (phi_m / n) kappa_m, the
  // coupler's bound on an explicit window (the undrained wave) reads it.
  modulus_.assign(cells, 0.0);
  std::vector<double> fluid_fraction(cells, 0.0);
  for (std::size_t m = 0; m < state.materials.size(); ++m) {
    const MaterialState<Dim>& material = state.materials[m];
    const EquationOfState& eos = *solver.materials()[m].eos;
    for (std::size_t c = 0; c < cells; ++c) {
      fluid_fraction[c] += material.volume_fraction[c];
      modulus_[c] += material.volume_fraction[c] *
                     eos.adiabatic_compressibility(material.density[c], material.temperature[c]);
    }
  }
  for (std::size_t c = 0; c < cells; ++c)
    modulus_[c] = modulus_[c] > 0.0 ? fluid_fraction[c] / modulus_[c] : 0.0;
  participant.write(f::pore_fluid_bulk_modulus.name, modulus_);
  if (description_.heat_exchange) {
    // The fluids' heat capacity and their capacity-weighted temperature.
    capacity_.assign(cells, 0.0);
    temperature_.assign(cells, 0.0);
    for (std::size_t m = 0; m < state.materials.size(); ++m) {
      const double c_v = solver.materials()[m].eos->specific_heat();
      for (std::size_t c = 0; c < cells; ++c) {
        const double capacity = state.materials[m].bulk_density[c] * c_v;
        capacity_[c] += capacity;
        temperature_[c] += capacity * state.materials[m].temperature[c];
      }
    }
    for (std::size_t c = 0; c < cells; ++c) temperature_[c] /= capacity_[c];
    participant.write(f::fluid_temperature.name, temperature_);
    participant.write(f::fluid_heat_capacity.name, capacity_);
  }
}

template class PorousCoupling<1>;
template class PorousCoupling<2>;
template class PorousCoupling<3>;

}  // namespace ice
