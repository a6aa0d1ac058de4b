#include "mpm/particles/particles.hpp"

#include <algorithm>
#include <numeric>

namespace mpm {

Voigt to_voigt(const Tensor& t) {
  return {t(0, 0),
          t(1, 1),
          t(2, 2),
          0.5 * (t(0, 1) + t(1, 0)),
          0.5 * (t(1, 2) + t(2, 1)),
          0.5 * (t(0, 2) + t(2, 0))};
}

Tensor from_voigt(const Voigt& v) {
  Tensor t;
  t << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
  return t;
}

template <int Dim>
void Particles<Dim>::resize(std::size_t n) {
  position.resize(n, Vec<Dim>::Zero());
  velocity.resize(n, Vec<Dim>::Zero());
  deformation_gradient.resize(n, Mat<Dim>::Identity());
  half_length.resize(n, Vec<Dim>::Zero());
  mass.resize(n, 0.0);
  initial_volume.resize(n, 0.0);
  volume.resize(n, 0.0);
  stress.resize(n, Voigt{});
  plastic_strain.resize(n, 0.0);
  damage.resize(n, 0.0);
  internal.resize(n, std::array<double, 2>{});
  porosity.resize(n, 0.0);
  initial_porosity.resize(n, 0.0);
  permeability.resize(n, 0.0);
  grain_size.resize(n, 0.0);
  pore_pressure.resize(n, 0.0);
  temperature.resize(n, 0.0);
  temperature_gradient.resize(n, Vec<Dim>::Zero());
  heat_capacity.resize(n, 0.0);
  external_force.resize(n, Vec<Dim>::Zero());
  external_heat.resize(n, 0.0);
  body.resize(n, 0);
  const std::size_t old = id.size();
  id.resize(n);
  for (std::size_t i = old; i < n; ++i) id[i] = i;
}

template <int Dim>
void Particles<Dim>::sort_by_id() {
  if (std::is_sorted(id.begin(), id.end())) return;
  std::vector<std::size_t> order(size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
  for_each_array([&](auto& array) {
    auto sorted = array;
    for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = array[order[k]];
    array.swap(sorted);
  });
}

template <int Dim>
double Particles<Dim>::bytes_per_particle() const {
  double total = 0.0;
  for_each_array([&total](const auto& v) {
    total +=
        static_cast<double>(v.capacity() * sizeof(typename std::decay_t<decltype(v)>::value_type));
  });
  return size() == 0 ? 0.0 : total / static_cast<double>(size());
}

template struct Particles<2>;
template struct Particles<3>;

}  // namespace mpm
