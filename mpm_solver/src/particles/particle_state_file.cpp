#include "mpm/particles/particle_state_file.hpp"

#include <algorithm>
#include <numeric>
#include <type_traits>

namespace mpm {

template <int Dim>
void write_particles(cosim::StateFileWriter& out, const Particles<Dim>& p) {
  out.rows("particles.position", p.position);
  out.rows("particles.velocity", p.velocity);
  out.rows("particles.deformation_gradient", p.deformation_gradient);
  out.rows("particles.half_length", p.half_length);
  out.numbers("particles.mass", p.mass);
  out.numbers("particles.initial_volume", p.initial_volume);
  out.numbers("particles.volume", p.volume);
  out.rows("particles.stress", p.stress);
  out.numbers("particles.plastic_strain", p.plastic_strain);
  out.numbers("particles.damage", p.damage);
  out.rows("particles.internal", p.internal);
  out.numbers("particles.porosity", p.porosity);
  out.numbers("particles.initial_porosity", p.initial_porosity);
  out.numbers("particles.permeability", p.permeability);
  out.numbers("particles.grain_size", p.grain_size);
  out.numbers("particles.pore_pressure", p.pore_pressure);
  out.numbers("particles.temperature", p.temperature);
  out.rows("particles.temperature_gradient", p.temperature_gradient);
  out.numbers("particles.heat_capacity", p.heat_capacity);
  out.rows("particles.external_force", p.external_force);
  out.numbers("particles.external_heat", p.external_heat);
  const std::vector<std::int64_t> body(p.body.begin(), p.body.end());
  out.integers("particles.body", body);
  const std::vector<std::int64_t> id(p.id.begin(), p.id.end());
  out.integers("particles.id", id);
}

template <int Dim>
void read_particles(const cosim::StateFileReader& in, Particles<Dim>& p) {
  const std::size_t n = p.size();
  in.rows("particles.position", n, p.position);
  in.rows("particles.velocity", n, p.velocity);
  in.rows("particles.deformation_gradient", n, p.deformation_gradient);
  in.rows("particles.half_length", n, p.half_length);
  in.numbers("particles.mass", n, p.mass);
  in.numbers("particles.initial_volume", n, p.initial_volume);
  in.numbers("particles.volume", n, p.volume);
  in.rows("particles.stress", n, p.stress);
  in.numbers("particles.plastic_strain", n, p.plastic_strain);
  in.numbers("particles.damage", n, p.damage);
  in.rows("particles.internal", n, p.internal);
  in.numbers("particles.porosity", n, p.porosity);
  in.numbers("particles.initial_porosity", n, p.initial_porosity);
  in.numbers("particles.permeability", n, p.permeability);
  in.numbers("particles.grain_size", n, p.grain_size);
  in.numbers("particles.pore_pressure", n, p.pore_pressure);
  in.numbers("particles.temperature", n, p.temperature);
  in.rows("particles.temperature_gradient", n, p.temperature_gradient);
  in.numbers("particles.heat_capacity", n, p.heat_capacity);
  in.rows("particles.external_force", n, p.external_force);
  in.numbers("particles.external_heat", n, p.external_heat);
  std::vector<std::int64_t> body;
  in.integers("particles.body", n, body);
  for (std::size_t i = 0; i < n; ++i) p.body[i] = static_cast<std::uint32_t>(body[i]);
  // A checkpoint of one process: a point's index is its id.
  std::vector<std::int64_t> id(n);
  std::iota(id.begin(), id.end(), std::int64_t{0});
  if (in.has("particles.id")) in.integers("particles.id", n, id);
  for (std::size_t i = 0; i < n; ++i) p.id[i] = static_cast<std::uint64_t>(id[i]);
}

template <int Dim>
void read_particles(std::span<const cosim::StateFileReader* const> parts, Particles<Dim>& p) {
  std::vector<std::size_t> counts;
  std::size_t total = 0;
  for (const auto* in : parts) {
    counts.push_back(in->numbers("particles.mass").size());
    total += counts.back();
  }
  p.resize(total);
  std::size_t at = 0;
  Particles<Dim> part;
  for (std::size_t f = 0; f < parts.size(); ++f) {
    part.resize(0);
    part.resize(counts[f]);
    read_particles(*parts[f], part);
    std::size_t array = 0;
    part.for_each_array([&](const auto& from) {
      std::size_t k = 0;
      p.for_each_array([&](auto& to) {
        if constexpr (std::is_same_v<std::decay_t<decltype(to)>, std::decay_t<decltype(from)>>)
          if (k == array)
            std::copy(from.begin(), from.end(), to.begin() + static_cast<std::ptrdiff_t>(at));
        ++k;
      });
      ++array;
    });
    at += counts[f];
  }
  p.sort_by_id();
}

template void read_particles<2>(std::span<const cosim::StateFileReader* const>, Particles<2>&);
template void read_particles<3>(std::span<const cosim::StateFileReader* const>, Particles<3>&);
template void write_particles<2>(cosim::StateFileWriter&, const Particles<2>&);
template void write_particles<3>(cosim::StateFileWriter&, const Particles<3>&);
template void read_particles<2>(const cosim::StateFileReader&, Particles<2>&);
template void read_particles<3>(const cosim::StateFileReader&, Particles<3>&);

}  // namespace mpm
