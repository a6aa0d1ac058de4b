#include "mpm/grid/grid.hpp"

#include <algorithm>
#include <cmath>

#include "mpm/shape/shape_dispatch.hpp"

namespace mpm {
namespace {

// Grid values per direction and their positions (in cells from the origin),
// as the run's kernel places them (shape_kernel.hpp).
int dofs_per_direction(ShapeKind shape, int cells) {
  return with_kernel<1>(shape, [&](auto kernel) { return decltype(kernel)::dofs(cells); });
}

double dof_coordinate(ShapeKind shape, int i, int cells) {
  return with_kernel<1>(shape,
                        [&](auto kernel) { return decltype(kernel)::dof_coordinate(i, cells); });
}

}  // namespace

template <int Dim>
std::size_t Grid<Dim>::flat(const std::array<int, Dim>& index) const {
  std::size_t f = 0;
  for (int d = Dim - 1; d >= 0; --d) f = f * static_cast<std::size_t>(dofs[d]) + index[d];
  return f;
}

template <int Dim>
std::array<int, Dim> Grid<Dim>::unflat(std::size_t flat_index) const {
  std::array<int, Dim> index{};
  for (int d = 0; d < Dim; ++d) {
    index[d] = static_cast<int>(flat_index % static_cast<std::size_t>(dofs[d]));
    flat_index /= static_cast<std::size_t>(dofs[d]);
  }
  return index;
}

template <int Dim>
Vec<Dim> Grid<Dim>::position(std::size_t flat_index) const {
  const auto index = unflat(flat_index);
  Vec<Dim> x;
  for (int d = 0; d < Dim; ++d)
    x[d] = origin[d] + spacing[d] * dof_coordinate(shape, index[d], cells[d]);
  return x;
}

template <int Dim>
int Grid<Dim>::cell_row_of_plane(int plane) const {
  const int rows = cells[Dim - 1];
  const double row = std::floor(dof_coordinate(shape, plane, rows));
  return static_cast<int>(std::clamp(row, 0.0, static_cast<double>(rows - 1)));
}

template <int Dim>
std::size_t Grid<Dim>::cell_count() const {
  std::size_t n = 1;
  for (int d = 0; d < Dim; ++d) n *= static_cast<std::size_t>(cells[d]);
  return n;
}

template <int Dim>
std::array<int, Dim> Grid<Dim>::cell_of(const Vec<Dim>& x) const {
  std::array<int, Dim> cell{};
  for (int d = 0; d < Dim; ++d) {
    const double xi = std::floor((x[d] - origin[d]) / spacing[d]);
    cell[d] = static_cast<int>(std::clamp(xi, 0.0, static_cast<double>(cells[d] - 1)));
  }
  return cell;
}

template <int Dim>
std::size_t Grid<Dim>::cell_flat(const std::array<int, Dim>& cell) const {
  std::size_t f = 0;
  for (int d = Dim - 1; d >= 0; --d) f = f * static_cast<std::size_t>(cells[d]) + cell[d];
  return f;
}

template <int Dim>
Vec<Dim> Grid<Dim>::upper() const {
  Vec<Dim> u;
  for (int d = 0; d < Dim; ++d) u[d] = origin[d] + spacing[d] * cells[d];
  return u;
}

template <int Dim>
bool Grid<Dim>::contains(const Vec<Dim>& x) const {
  const Vec<Dim> u = upper();
  for (int d = 0; d < Dim; ++d)
    if (!(x[d] >= origin[d] && x[d] <= u[d])) return false;
  return true;
}

template <int Dim>
std::size_t Grid<Dim>::plane_size() const {
  std::size_t n = 1;
  for (int d = 0; d + 1 < Dim; ++d) n *= static_cast<std::size_t>(dofs[d]);
  return n;
}

template <int Dim>
std::size_t Grid<Dim>::owned_begin() const {
  return owned_planes == 0
             ? 0
             : static_cast<std::size_t>(owned_first_plane - first_plane) * plane_size();
}

template <int Dim>
std::size_t Grid<Dim>::owned_end() const {
  return owned_planes == 0 ? values
                           : owned_begin() + static_cast<std::size_t>(owned_planes) * plane_size();
}

template <int Dim>
void Grid<Dim>::allocate(int field_count) {
  fields = field_count;
  const int planes = stored_planes == 0 ? dofs[Dim - 1] : stored_planes;
  values = plane_size() * static_cast<std::size_t>(planes);
  const std::size_t n = values * static_cast<std::size_t>(fields);
  mass.assign(n, 0.0);
  momentum.assign(n, Vec<Dim>::Zero());
  force.assign(n, Vec<Dim>::Zero());
  velocity.assign(n, Vec<Dim>::Zero());
  velocity_change.assign(n, Vec<Dim>::Zero());
  mass_gradient.assign(fields > 1 ? n : 0, Vec<Dim>::Zero());
  remapped_velocity.assign(n, Vec<Dim>::Zero());
}

template <int Dim>
void Grid<Dim>::allocate_heat() {
  for (auto* array : {&heat_capacity, &temperature, &heat_rate, &temperature_change})
    array->assign(size(), 0.0);
}

template <int Dim>
void Grid<Dim>::clear() {
  std::fill(mass.begin(), mass.end(), 0.0);
  std::fill(momentum.begin(), momentum.end(), Vec<Dim>::Zero());
  std::fill(force.begin(), force.end(), Vec<Dim>::Zero());
  std::fill(mass_gradient.begin(), mass_gradient.end(), Vec<Dim>::Zero());
}

template <int Dim>
Grid<Dim> make_grid(const Vec<Dim>& origin, const Vec<Dim>& spacing,
                    const std::array<int, Dim>& cells, ShapeKind shape) {
  Grid<Dim> grid;
  grid.origin = origin;
  grid.spacing = spacing;
  grid.cells = cells;
  grid.shape = shape;
  for (int d = 0; d < Dim; ++d) grid.dofs[d] = dofs_per_direction(shape, cells[d]);
  grid.allocate(1);
  return grid;
}

template struct Grid<2>;
template struct Grid<3>;
template Grid<2> make_grid<2>(const Vec<2>&, const Vec<2>&, const std::array<int, 2>&, ShapeKind);
template Grid<3> make_grid<3>(const Vec<3>&, const Vec<3>&, const std::array<int, 3>&, ShapeKind);

}  // namespace mpm
