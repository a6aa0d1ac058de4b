#include "ice/advection/advection_time_step.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "ice/grid/face_walk.hpp"

namespace ice {

template <int Dim>
double advection_rate(const CellGrid<Dim>& grid, const FaceField<Dim>& face_velocity,
                      std::span<const unsigned char> counted) {
  for (int d = 0; d < Dim; ++d) {
    if (face_velocity[d].size() != static_cast<std::size_t>(grid.face_count(d))) {
      throw std::invalid_argument("advection_rate: " + std::to_string(face_velocity[d].size()) +
                                  " face velocities normal to direction " + std::to_string(d) +
                                  " for " + std::to_string(grid.face_count(d)) + " faces");
    }
  }
  double rate = 0.0;
  // Row by row along x: within a row a cell's lower face normal to d is the
  // cell index plus a constant (no index division per cell).
  for_each_row(grid, [&](int first, int length) {
    std::array<const double*, Dim> lower{};
    for (int d = 0; d < Dim; ++d) {
      lower[d] = face_velocity[d].data() + lower_face_offset(grid, d, first);
    }
    for (int c = first; c < first + length; ++c) {
      double cell_rate = 0.0;
      for (int d = 0; d < Dim; ++d) {
        const double* u = lower[d];
        cell_rate += std::max(std::abs(u[c]), std::abs(u[c + grid.stride(d)])) / grid.spacing()[d];
      }
      if (counted.empty() || counted[static_cast<std::size_t>(c)] != 0)
        rate = std::max(rate, cell_rate);
    }
  });
  return rate;
}

template <int Dim>
double advection_time_step(const CellGrid<Dim>& grid, const FaceField<Dim>& face_velocity,
                           double courant) {
  const double rate = advection_rate(grid, face_velocity);
  return rate > 0.0 ? courant / rate : std::numeric_limits<double>::infinity();
}

template double advection_rate(const CellGrid<1>&, const FaceField<1>&,
                               std::span<const unsigned char>);
template double advection_rate(const CellGrid<2>&, const FaceField<2>&,
                               std::span<const unsigned char>);
template double advection_rate(const CellGrid<3>&, const FaceField<3>&,
                               std::span<const unsigned char>);
template double advection_time_step(const CellGrid<1>&, const FaceField<1>&, double);
template double advection_time_step(const CellGrid<2>&, const FaceField<2>&, double);
template double advection_time_step(const CellGrid<3>&, const FaceField<3>&, double);

}  // namespace ice
