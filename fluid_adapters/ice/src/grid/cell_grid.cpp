#include "ice/grid/cell_grid.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ice {

template <int Dim>
CellGrid<Dim>::CellGrid(const Point& origin, const Point& spacing, const CellIndex& cells)
    : origin_(origin), spacing_(spacing), cells_(cells) {
  long long count = 1;
  for (int d = 0; d < Dim; ++d) {
    const std::string axis = "direction " + std::to_string(d);
    if (!std::isfinite(origin[d])) {
      throw std::invalid_argument("CellGrid: origin is not finite in " + axis);
    }
    if (!(spacing[d] > 0.0) || !std::isfinite(spacing[d])) {
      throw std::invalid_argument("CellGrid: spacing must be positive and finite in " + axis +
                                  ", got " + std::to_string(spacing[d]));
    }
    if (cells[d] < 1) {
      throw std::invalid_argument("CellGrid: needs at least one cell in " + axis + ", got " +
                                  std::to_string(cells[d]));
    }
    count *= cells[d];
    if (count * 2 > std::numeric_limits<int>::max()) {
      throw std::invalid_argument("CellGrid: too many cells for int face indices");
    }
  }
  cell_count_ = static_cast<int>(count);
  cell_volume_ = spacing.prod();
  int stride = 1;
  for (int d = 0; d < Dim; ++d) {
    stride_[d] = stride;
    stride *= cells[d];
    face_count_[d] = cell_count_ / cells[d] * (cells[d] + 1);
  }
}

template <int Dim>
typename CellGrid<Dim>::Point CellGrid<Dim>::upper() const {
  Point top = origin_;
  for (int d = 0; d < Dim; ++d) {
    top[d] += cells_[d] * spacing_[d];
  }
  return top;
}

template <int Dim>
int CellGrid<Dim>::cell(const CellIndex& ijk) const {
  int index = 0;
  for (int d = Dim - 1; d >= 0; --d) {
    index = index * cells_[d] + ijk[d];
  }
  return index;
}

template <int Dim>
typename CellGrid<Dim>::CellIndex CellGrid<Dim>::cell_ijk(int cell) const {
  CellIndex ijk{};
  for (int d = 0; d < Dim; ++d) {
    ijk[d] = cell % cells_[d];
    cell /= cells_[d];
  }
  return ijk;
}

template <int Dim>
int CellGrid<Dim>::face(int normal, const CellIndex& ijk) const {
  int index = 0;
  for (int d = Dim - 1; d >= 0; --d) {
    index = index * (cells_[d] + (d == normal ? 1 : 0)) + ijk[d];
  }
  return index;
}

template <int Dim>
typename CellGrid<Dim>::CellIndex CellGrid<Dim>::face_ijk(int normal, int face) const {
  CellIndex ijk{};
  for (int d = 0; d < Dim; ++d) {
    const int n = cells_[d] + (d == normal ? 1 : 0);
    ijk[d] = face % n;
    face /= n;
  }
  return ijk;
}

// A face f normal to d sits in row `outer` = f / (s (n + 1)) at position
// i = (f / s) mod (n + 1), s = stride(d), n = cells[d]; the cell i of that
// row is f - s outer.
template <int Dim>
int CellGrid<Dim>::neighbour(int cell, int direction, int side) const {
  const int s = stride_[direction];
  const int i = (cell / s) % cells_[direction] + side;
  return i < 0 || i >= cells_[direction] ? -1 : cell + side * s;
}

template <int Dim>
typename CellGrid<Dim>::Point CellGrid<Dim>::cell_centre(int cell) const {
  const CellIndex ijk = cell_ijk(cell);
  Point x;
  for (int d = 0; d < Dim; ++d) {
    x[d] = origin_[d] + (ijk[d] + 0.5) * spacing_[d];
  }
  return x;
}

template <int Dim>
typename CellGrid<Dim>::Point CellGrid<Dim>::face_centre(int normal, int face) const {
  const CellIndex ijk = face_ijk(normal, face);
  Point x;
  for (int d = 0; d < Dim; ++d) {
    x[d] = origin_[d] + (ijk[d] + (d == normal ? 0.0 : 0.5)) * spacing_[d];
  }
  return x;
}

template class CellGrid<1>;
template class CellGrid<2>;
template class CellGrid<3>;

}  // namespace ice
