#include "ice/coupling/porous_coupling.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cosim/job/job.hpp"
#include "ice/io/state_output.hpp"

namespace ice {

namespace {

namespace mx = cosim::job::momentum_exchange_fields;
namespace ex = cosim::job::energy_exchange_fields;
constexpr const char* pore_pressure = "pore_pressure";
constexpr const char* pore_pressure_force = "pore_pressure_force";

cosim::FieldSpec field(const char* name, int components, const char* unit) {
  cosim::FieldSpec f;
  f.name = name;
  f.mesh = PorousCoupling<1>::mesh_name;
  f.components = components;
  f.unit = unit;
  return f;
}

cosim::FieldSpec impulse_field(int components) {
  cosim::FieldSpec impulse = field(mx::impulse, components, "kg m/s");
  impulse.quantity = cosim::Quantity::extensive;
  impulse.time = cosim::TimeTreatment::integral;
  return impulse;
}

}  // namespace

template <int Dim>
void PorousCoupling<Dim>::declare(cosim::Participant& participant, IceSolver<Dim>& solver) {
  participant.declare_mesh(cell_mesh(solver.grid(), mesh_name));
  cosim::FieldSpec fraction = field(mx::solid_fraction, 1, "1");
  fraction.lower_bound = 0.0;
  fraction.upper_bound = 1.0;
  participant.declare_read(fraction, 0.0);
  participant.declare_read(field(mx::solid_velocity, Dim, "m/s"), 0.0);
  if (description_.drag_in_solver) {
    cosim::FieldSpec density = field(mx::solid_bulk_density, 1, "kg/m^3");
    density.lower_bound = 0.0;
    participant.declare_read(density, 0.0);
    cosim::FieldSpec drag = field(mx::drag_coefficient, 1, "kg/(m^3 s)");
    drag.lower_bound = 0.0;
    participant.declare_read(drag, 0.0);
    participant.declare_write(impulse_field(Dim));
  } else {
    participant.declare_read(impulse_field(Dim), 0.0);
  }
  participant.declare_write(field(pore_pressure, 1, "Pa"));
  cosim::FieldSpec force = field(pore_pressure_force, Dim, "N");
  force.quantity = cosim::Quantity::extensive;
  participant.declare_write(force);
  participant.declare_write(field(mx::fluid_velocity, Dim, "m/s"));
  cosim::FieldSpec density = field(mx::fluid_bulk_density, 1, "kg/m^3");
  density.lower_bound = 0.0;
  participant.declare_write(density);
  cosim::FieldSpec modulus = field(mx::pore_fluid_bulk_modulus, 1, "Pa");
  modulus.lower_bound = 0.0;
  participant.declare_write(modulus);
  if (description_.heat_exchange) {
    participant.declare_write(field(ex::fluid_temperature, 1, "K"));
    cosim::FieldSpec capacity = field(ex::fluid_heat_capacity, 1, "J/(m^3 K)");
    capacity.lower_bound = 0.0;
    participant.declare_write(capacity);
    cosim::FieldSpec heat = field(ex::heat, 1, "J");
    heat.quantity = cosim::Quantity::extensive;
    heat.time = cosim::TimeTreatment::integral;
    participant.declare_read(heat, 0.0);
  }
  write_fields(participant, solver);
}

template <int Dim>
void PorousCoupling<Dim>::read_medium(const cosim::Participant& participant, IceSolver<Dim>& solver,
                                      bool first_window) {
  const auto cells = static_cast<std::size_t>(solver.grid().cell_count());
  const auto dim = static_cast<std::size_t>(Dim);
  buffer_.resize(cells * dim);
  porosity_.resize(cells);
  participant.read(mx::solid_fraction, std::span<double>(buffer_.data(), cells));
  for (std::size_t c = 0; c < cells; ++c)
    porosity_[c] = std::clamp(1.0 - buffer_[c], description_.minimum_porosity, 1.0);
  participant.read(mx::solid_velocity, buffer_);
  for (std::size_t d = 0; d < dim; ++d) {
    solid_velocity_[d].resize(cells);
    for (std::size_t c = 0; c < cells; ++c) solid_velocity_[d][c] = buffer_[c * dim + d];
  }
  if (description_.drag_in_solver) {
    drag_.resize(cells);
    solid_density_.resize(cells);
    participant.read(mx::drag_coefficient, drag_);
    participant.read(mx::solid_bulk_density, solid_density_);
  }
  solver.set_porous_medium(porosity_, solid_velocity_,
                           first_window ? PorosityChange::fill_pores : PorosityChange::compress);
  if (description_.drag_in_solver) solver.set_solid_drag(drag_, solid_density_);
  if (!warned_) {
    warned_ = true;
    const double limit = explicit_window_limit(solver);
    if (participant.window_size() > limit) {
      spdlog::warn(
          "ice coupling: the window {:.3g} s is longer than the {:.3g} s the pore water's pressure "
          "wave takes across an exchange cell holding solid; the explicit exchange of porosity "
          "and pore pressure may be unstable (DESIGN.md §3): use window <= {:.2g} s",
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
    participant.read_increment(ex::heat, dt, buffer_);
    solver.add_heat(buffer_);
  }
  buffer_.resize(size);
  if (!description_.drag_in_solver) {
    participant.read_increment(mx::impulse, dt, buffer_);
    solver.add_momentum(buffer_);
    return;
  }
  // The impulse is an integral field: its rate over this step.
  solver.take_solid_impulse(buffer_);
  for (double& j : buffer_) j /= dt;
  participant.write(mx::impulse, buffer_);
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
  participant.write(pore_pressure, state.pressure);
  force_.resize(cells * dim);
  solver.solid_pressure_force(force_);
  participant.write(pore_pressure_force, force_);
  participant.write(mx::fluid_velocity, velocity_);
  participant.write(mx::fluid_bulk_density, density_);
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
  participant.write(mx::pore_fluid_bulk_modulus, modulus_);
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
    participant.write(ex::fluid_temperature, temperature_);
    participant.write(ex::fluid_heat_capacity, capacity_);
  }
}

template class PorousCoupling<1>;
template class PorousCoupling<2>;
template class PorousCoupling<3>;

}  // namespace ice
