#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "mpm/core/tensor.hpp"
#include "mpm/shape/shape_kernel.hpp"

namespace mpm {

// The uniform background grid and the values it carries for one step. The
// grid values sit where the shape kernel puts them (nodes for linear and
// GIMP, B-spline control points at the Greville abscissae); `dofs` counts
// them per direction, x fastest in the flat index.
template <int Dim>
struct Grid {
  Vec<Dim> origin = Vec<Dim>::Zero();
  Vec<Dim> spacing = Vec<Dim>::Ones();
  std::array<int, Dim> cells{};
  std::array<int, Dim> dofs{};
  ShapeKind shape = ShapeKind::linear;

  // Velocity fields: one per body when bodies meet through grid contact
  // (Bardenhagen), else one shared by every deformable body plus one per
  // rigid body. Arrays hold `fields * size()` entries, field-major:
  // index = field * size() + value.
  int fields = 1;
  // Per field and value: lumped mass, momentum, force, velocity after the
  // update, its change over the step (for FLIP), and the mass gradient
  // (contact normals; only with several fields).
  std::vector<double> mass;
  std::vector<Vec<Dim>> momentum;
  std::vector<Vec<Dim>> force;
  std::vector<Vec<Dim>> velocity;
  std::vector<Vec<Dim>> velocity_change;
  std::vector<Vec<Dim>> mass_gradient;
  // MUSL: the velocity re-mapped from the updated particle velocities.
  std::vector<Vec<Dim>> remapped_velocity;
  // Heat conduction, one field shared by every thermal body (empty unless
  // allocate_heat): heat capacity sum N m c [J/K], temperature [K], heat
  // rate of conduction and external sources [W], and the temperature
  // change over the step [K].
  std::vector<double> heat_capacity;
  std::vector<double> temperature;
  std::vector<double> heat_rate;
  std::vector<double> temperature_change;

  // Grid values per field, stored.
  std::size_t size() const { return values; }
  std::size_t values = 0;
  // The planes of grid values (along the last direction) the arrays hold:
  // all of them on one process; on one rank of a grid decomposed into slabs
  // of cell rows (issue 27), the planes of its rows and the ghost planes its
  // points touch. A stored value's index is its flat index minus
  // first_value(); owned_begin()..owned_end() are the stored values this
  // rank sums and updates (all of them on one process).
  int first_plane = 0;
  int stored_planes = 0;  // 0: every plane
  int owned_first_plane = 0;
  int owned_planes = 0;  // 0: every stored plane
  std::size_t plane_size() const;
  std::size_t first_value() const { return static_cast<std::size_t>(first_plane) * plane_size(); }
  std::size_t owned_begin() const;
  std::size_t owned_end() const;
  // Flat index of the stored value `i`.
  std::size_t flat_of_stored(std::size_t i) const { return i + first_value(); }
  std::size_t flat(const std::array<int, Dim>& index) const;
  std::array<int, Dim> unflat(std::size_t flat_index) const;
  // Position of a grid value.
  Vec<Dim> position(std::size_t flat_index) const;
  double cell_volume() const { return spacing.prod(); }
  double min_spacing() const { return spacing.minCoeff(); }
  std::size_t cell_count() const;
  // The cell row (along the last direction) a plane of values lies in,
  // clamped to the grid.
  int cell_row_of_plane(int plane) const;
  // Cell holding x (clamped to the grid), and its flat index.
  std::array<int, Dim> cell_of(const Vec<Dim>& x) const;
  std::size_t cell_flat(const std::array<int, Dim>& cell) const;
  Vec<Dim> upper() const;
  bool contains(const Vec<Dim>& x) const;

  // Sizes the arrays for `fields` velocity fields (values from dofs and
  // the stored planes).
  void allocate(int field_count);
  // Sizes the heat arrays (one field).
  void allocate_heat();
  // Zeroes every array before a particle-to-grid pass.
  void clear();
};

template <int Dim>
Grid<Dim> make_grid(const Vec<Dim>& origin, const Vec<Dim>& spacing,
                    const std::array<int, Dim>& cells, ShapeKind shape);

extern template struct Grid<2>;
extern template struct Grid<3>;

}  // namespace mpm
