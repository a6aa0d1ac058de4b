#include "ice/coupling/porous_coupling.hpp"

#include <algorithm>
#include <limits>

#include "cosim/job/job.hpp"
#include "ice/io/state_output.hpp"

namespace ice {

namespace {

namespace mx = cosim::job::momentum_exchange_fields;
constexpr const char* pore_pressure = "pore_pressure";

cosim::FieldSpec field(const char* name, int components, const char* unit) {
  cosim::FieldSpec f;
  f.name = name;
  f.mesh = PorousCoupling<1>::mesh_name;
  f.components = components;
  f.unit = unit;
  return f;
}

}  // namespace

template <int Dim>
void PorousCoupling<Dim>::declare(cosim::Participant& participant, const IceSolver<Dim>& solver) {
  participant.declare_mesh(cell_mesh(solver.grid(), mesh_name));
  cosim::FieldSpec fraction = field(mx::solid_fraction, 1, "1");
  fraction.lower_bound = 0.0;
  fraction.upper_bound = 1.0;
  participant.declare_read(fraction, 0.0);
  participant.declare_read(field(mx::solid_velocity, Dim, "m/s"), 0.0);
  cosim::FieldSpec impulse = field(mx::impulse, Dim, "kg m/s");
  impulse.quantity = cosim::Quantity::extensive;
  impulse.time = cosim::TimeTreatment::integral;
  participant.declare_read(impulse, 0.0);
  participant.declare_write(field(pore_pressure, 1, "Pa"));
  participant.declare_write(field(mx::fluid_velocity, Dim, "m/s"));
  cosim::FieldSpec density = field(mx::fluid_bulk_density, 1, "kg/m^3");
  density.lower_bound = 0.0;
  participant.declare_write(density);
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
    porosity_[c] = std::clamp(1.0 - buffer_[c], minimum_porosity_, 1.0);
  participant.read(mx::solid_velocity, buffer_);
  for (std::size_t d = 0; d < dim; ++d) {
    solid_velocity_[d].resize(cells);
    for (std::size_t c = 0; c < cells; ++c) solid_velocity_[d][c] = buffer_[c * dim + d];
  }
  solver.set_porous_medium(porosity_, solid_velocity_,
                           first_window ? PorosityChange::fill_pores : PorosityChange::compress);
}

template <int Dim>
void PorousCoupling<Dim>::add_impulse(cosim::Participant& participant, double dt,
                                      IceSolver<Dim>& solver) {
  buffer_.resize(static_cast<std::size_t>(solver.grid().cell_count()) *
                 static_cast<std::size_t>(Dim));
  participant.read_increment(mx::impulse, dt, buffer_);
  solver.add_momentum(buffer_);
}

template <int Dim>
void PorousCoupling<Dim>::write_fields(cosim::Participant& participant,
                                       const IceSolver<Dim>& solver) {
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
  participant.write(mx::fluid_velocity, velocity_);
  participant.write(mx::fluid_bulk_density, density_);
}

template class PorousCoupling<1>;
template class PorousCoupling<2>;
template class PorousCoupling<3>;

}  // namespace ice
