#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpm/core/tensor.hpp"

namespace mpm {

// Symmetric 3 x 3 tensor in Voigt order xx, yy, zz, xy, yz, xz.
using Voigt = std::array<double, 6>;
Voigt to_voigt(const Tensor& t);
Tensor from_voigt(const Voigt& v);

// The material points, as structure-of-arrays: one vector per quantity,
// indexed by particle. On one process a point's index is its id for the
// whole run, and the points of a body are contiguous. On a rank of a
// decomposed run (issue 27) a rank holds the points of its cells, in id
// order.
template <int Dim>
struct Particles {
  // Kinematics.
  std::vector<Vec<Dim>> position;
  std::vector<Vec<Dim>> velocity;
  std::vector<Mat<Dim>> deformation_gradient;
  std::vector<Vec<Dim>>
      half_length;  // GIMP domain half-length, initial or deformed (GimpDomain) [m]
  // Mass and volume.
  std::vector<double> mass;
  std::vector<double> initial_volume;
  std::vector<double> volume;
  // Stress and material state (see MaterialState).
  std::vector<Voigt> stress;  // effective Cauchy stress sigma', tension positive [Pa]
  std::vector<double> plastic_strain;
  std::vector<double> damage;
  std::vector<std::array<double, 2>> internal;
  // Porous medium (Pan et al. 2021, eqs. 74-76; Tran et al., MPMICE, eq. 3).
  std::vector<double> porosity;
  std::vector<double> initial_porosity;
  std::vector<double> permeability;   // intrinsic [m^2]
  std::vector<double> grain_size;     // D50 [m]
  std::vector<double> pore_pressure;  // received from the fluid [Pa]
  // Heat (Tran et al., MPMICE, eq. 9): temperature and heat capacity m c,
  // 0 for the points of bodies that are not thermal.
  std::vector<double> temperature;             // [K]
  std::vector<Vec<Dim>> temperature_gradient;  // [K/m], from the grid of the last step
  std::vector<double> heat_capacity;           // [J/K] (per unit depth in 2D)
  // Forces and heat applied from outside the grid solve: surface loads, coupling.
  std::vector<Vec<Dim>> external_force;  // [N] (per unit depth in 2D)
  std::vector<double> external_heat;     // [W] (per unit depth in 2D)
  // Owner.
  std::vector<std::uint32_t> body;
  // The point's index among all the run's points, in seeding order.
  std::vector<std::uint64_t> id;

  std::size_t size() const { return mass.size(); }
  // New points get the ids that follow the last index.
  void resize(std::size_t n);
  // Calls f(array) for every per-particle array above, in their order (a
  // particle's whole state: what migrates with it between ranks).
  template <class F>
  void for_each_array(F&& f) {
    visit_arrays(*this, f);
  }
  template <class F>
  void for_each_array(F&& f) const {
    visit_arrays(*this, f);
  }
  // Puts the points in id order.
  void sort_by_id();
  // Bytes held per particle by these arrays (capacity included).
  double bytes_per_particle() const;

 private:
  template <class Self, class F>
  static void visit_arrays(Self& p, F& f) {
    f(p.position);
    f(p.velocity);
    f(p.deformation_gradient);
    f(p.half_length);
    f(p.mass);
    f(p.initial_volume);
    f(p.volume);
    f(p.stress);
    f(p.plastic_strain);
    f(p.damage);
    f(p.internal);
    f(p.porosity);
    f(p.initial_porosity);
    f(p.permeability);
    f(p.grain_size);
    f(p.pore_pressure);
    f(p.temperature);
    f(p.temperature_gradient);
    f(p.heat_capacity);
    f(p.external_force);
    f(p.external_heat);
    f(p.body);
    f(p.id);
  }
};

extern template struct Particles<2>;
extern template struct Particles<3>;

}  // namespace mpm
