#pragma once

#include <random>
#include <vector>

#include "mpm/coupling/body_roles.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"

// Particle sets built directly (no solver) for the coupling's unit tests.
namespace mpm::testing {

// Appends a block [lo, hi] of particles of size d (per direction) to `particles`.
template <int Dim>
void add_block(Particles<Dim>& particles, const Vec<Dim>& lo, const Vec<Dim>& hi, double d,
               double porosity, double grain_density, std::uint32_t body) {
  std::array<int, Dim> count{};
  std::size_t total = 1;
  for (int k = 0; k < Dim; ++k) {
    count[static_cast<std::size_t>(k)] = static_cast<int>(std::lround((hi[k] - lo[k]) / d));
    total *= static_cast<std::size_t>(count[static_cast<std::size_t>(k)]);
  }
  const std::size_t first = particles.size();
  particles.resize(first + total);
  const double volume = std::pow(d, Dim);
  for (std::size_t q = 0; q < total; ++q) {
    const std::size_t p = first + q;
    std::size_t rest = q;
    Vec<Dim> x;
    for (int k = 0; k < Dim; ++k) {
      const auto n = static_cast<std::size_t>(count[static_cast<std::size_t>(k)]);
      x[k] = lo[k] + (static_cast<double>(rest % n) + 0.5) * d;
      rest /= n;
    }
    particles.position[p] = x;
    particles.velocity[p].setZero();
    particles.half_length[p] = Vec<Dim>::Constant(0.5 * d);
    particles.volume[p] = particles.initial_volume[p] = volume;
    particles.porosity[p] = particles.initial_porosity[p] = porosity;
    particles.mass[p] = grain_density * (1.0 - porosity) * volume;
    particles.permeability[p] = 1e-10;
    particles.grain_size[p] = 1e-3;
    particles.body[p] = body;
  }
}

// n particles at random positions inside [lo, hi] with random masses,
// volumes, porosities and velocities.
template <int Dim>
Particles<Dim> random_particles(std::size_t n, const Vec<Dim>& lo, const Vec<Dim>& hi,
                                unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Particles<Dim> particles;
  particles.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    for (int k = 0; k < Dim; ++k) {
      particles.position[p][k] = lo[k] + u(rng) * (hi[k] - lo[k]);
      particles.velocity[p][k] = 2.0 * u(rng) - 1.0;
    }
    particles.half_length[p] = Vec<Dim>::Constant(0.01 + 0.02 * u(rng));
    particles.volume[p] = particles.initial_volume[p] = 1e-4 * (0.5 + u(rng));
    particles.porosity[p] = 0.2 + 0.4 * u(rng);
    particles.mass[p] = 2650.0 * (1.0 - particles.porosity[p]) * particles.volume[p];
    particles.permeability[p] = 1e-11 * (1.0 + u(rng));
    particles.grain_size[p] = 1e-3 * (1.0 + u(rng));
    particles.body[p] = 0;
  }
  return particles;
}

inline std::vector<coupling::BodyRole> porous_roles(std::size_t bodies = 1) {
  std::vector<coupling::BodyRole> roles(bodies);
  for (auto& r : roles) r.porous = true;
  return roles;
}

}  // namespace mpm::testing
