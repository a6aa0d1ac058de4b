#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>

namespace ice {

// A grid index (int, as the grid counts cells) as an array index.
inline std::size_t at(int i) {
  return static_cast<std::size_t>(i);
}

// The uniform Cartesian grid of the ICE solver: cells of one size, fields
// stored at cell centres (one value per cell) and face-normal values on the
// faces (one array per direction).
//
// Flat indices run x fastest. Cells: c = i + nx (j + ny k). Faces normal to
// direction d form the grid of cells[d] + 1 by the other cell counts, in the
// same order; face i along d of a row is the lower face of cell i of that row
// (face 0 and face cells[d] lie on the domain boundary).
template <int Dim>
class CellGrid {
  static_assert(Dim >= 1 && Dim <= 3, "CellGrid exists in 1D, 2D and 3D");

 public:
  using Point = Eigen::Matrix<double, Dim, 1>;
  using CellIndex = std::array<int, Dim>;

  // Throws std::invalid_argument for a non-positive or non-finite spacing, a
  // non-finite origin or a cell count below one.
  CellGrid(const Point& origin, const Point& spacing, const CellIndex& cells);

  const Point& origin() const { return origin_; }
  const Point& spacing() const { return spacing_; }
  const CellIndex& cells() const { return cells_; }
  Point upper() const;

  int cell_count() const { return cell_count_; }
  double cell_volume() const { return cell_volume_; }
  int face_count(int normal) const { return face_count_[normal]; }
  double face_area(int normal) const { return cell_volume_ / spacing_[normal]; }
  // Step of the flat cell index to the next cell along `direction`; the flat
  // face index along its own normal steps the same way.
  int stride(int direction) const { return stride_[direction]; }

  int cell(const CellIndex& ijk) const;
  CellIndex cell_ijk(int cell) const;
  // The face normal to `normal` on the lower side of cell `ijk`;
  // ijk[normal] runs to cells[normal] (the upper boundary face).
  int face(int normal, const CellIndex& ijk) const;
  CellIndex face_ijk(int normal, int face) const;

  int lower_face(int normal, int cell) const {
    return cell + stride_[normal] * (cell / (stride_[normal] * cells_[normal]));
  }
  int upper_face(int normal, int cell) const { return lower_face(normal, cell) + stride_[normal]; }
  // The cells on either side of a face; -1 outside the domain.
  int lower_cell(int normal, int face) const {
    const int s = stride_[normal];
    const int n = cells_[normal];
    const int i = (face / s) % (n + 1);
    return i == 0 ? -1 : face - s * (face / (s * (n + 1))) - s;
  }
  int upper_cell(int normal, int face) const {
    const int s = stride_[normal];
    const int n = cells_[normal];
    const int i = (face / s) % (n + 1);
    return i == n ? -1 : face - s * (face / (s * (n + 1)));
  }
  // The neighbour of `cell` one step along `direction` (side -1 or +1); -1
  // outside the domain.
  int neighbour(int cell, int direction, int side) const;

  Point cell_centre(int cell) const;
  Point face_centre(int normal, int face) const;

 private:
  Point origin_;
  Point spacing_;
  CellIndex cells_;
  CellIndex stride_{};
  CellIndex face_count_{};
  int cell_count_ = 0;
  double cell_volume_ = 0.0;
};

extern template class CellGrid<1>;
extern template class CellGrid<2>;
extern template class CellGrid<3>;

}  // namespace ice
