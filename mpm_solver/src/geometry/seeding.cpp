#include "mpm/geometry/seeding.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cosim/error.hpp"

namespace mpm {

template <int Dim>
int points_per_cell(const SeedingPattern& pattern) {
  if (pattern.kind == SeedingPattern::Kind::quasi_random && pattern.per_cell > 0)
    return pattern.per_cell;
  if (pattern.per_direction < 1)
    throw cosim::InputError("particles per direction must be at least 1, got " +
                            std::to_string(pattern.per_direction));
  int n = 1;
  for (int d = 0; d < Dim; ++d) n *= pattern.per_direction;
  return n;
}

double r_sequence_root(int d) {
  // Newton on f(x) = x^(d+1) - x - 1 from x = 2 (f convex for x > 0).
  double x = 2.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double power = std::pow(x, d);
    const double step = (power * x - x - 1.0) / ((d + 1) * power - 1.0);
    x -= step;
    if (std::abs(step) < 1e-16 * x) break;
  }
  return x;
}

template <int Dim>
std::vector<Vec<Dim>> cell_pattern(const SeedingPattern& pattern) {
  const int count = points_per_cell<Dim>(pattern);
  std::vector<Vec<Dim>> points;
  points.reserve(static_cast<std::size_t>(count));
  if (pattern.kind == SeedingPattern::Kind::regular) {
    const int n = pattern.per_direction;
    for (int k = 0; k < count; ++k) {
      Vec<Dim> p;
      int rest = k;
      for (int d = 0; d < Dim; ++d) {
        p[d] = (rest % n + 0.5) / n;
        rest /= n;
      }
      points.push_back(p);
    }
  } else {
    // van den Bout et al., eq. 88: x_k = k alpha mod 1.
    const double phi = r_sequence_root(Dim);
    Vec<Dim> alpha;
    for (int d = 0; d < Dim; ++d) alpha[d] = std::pow(phi, -(d + 1));
    for (int k = 1; k <= count; ++k) {
      Vec<Dim> p;
      for (int d = 0; d < Dim; ++d) {
        const double t = k * alpha[d];
        p[d] = t - std::floor(t);
      }
      points.push_back(p);
    }
  }
  return points;
}

template <int Dim>
SeededParticles<Dim> seed_cells(const std::function<bool(const Vec<Dim>&)>& inside,
                                const Box<Dim>& bounds, const GridGeometry<Dim>& grid,
                                const SeedingPattern& pattern) {
  for (int d = 0; d < Dim; ++d) {
    if (grid.cells[d] < 1 || !(grid.spacing[d] > 0.0))
      throw cosim::InputError("seeding needs a grid with cells and a positive spacing");
  }
  const std::vector<Vec<Dim>> local = cell_pattern<Dim>(pattern);
  const double n = static_cast<double>(local.size());
  const double volume = grid.cell_volume() / n;
  const Vec<Dim> half_length = grid.spacing / (2.0 * std::pow(n, 1.0 / Dim));

  // Cells the bounding box touches, clipped to the grid.
  std::array<int, Dim> lo{}, hi{};
  for (int d = 0; d < Dim; ++d) {
    const double a = std::floor((bounds.lower[d] - grid.origin[d]) / grid.spacing[d]);
    const double b = std::floor((bounds.upper[d] - grid.origin[d]) / grid.spacing[d]);
    lo[d] = static_cast<int>(std::clamp(a, 0.0, static_cast<double>(grid.cells[d])));
    hi[d] = static_cast<int>(std::clamp(b + 1.0, 0.0, static_cast<double>(grid.cells[d])));
    if (lo[d] >= hi[d]) return {};
  }

  SeededParticles<Dim> seeded;
  std::array<int, Dim> cell = lo;
  while (true) {
    Vec<Dim> corner;
    for (int d = 0; d < Dim; ++d) corner[d] = grid.origin[d] + grid.spacing[d] * cell[d];
    for (const Vec<Dim>& r : local) {
      const Vec<Dim> x = corner + r.cwiseProduct(grid.spacing);
      if (!inside(x)) continue;
      seeded.positions.push_back(x);
      seeded.volumes.push_back(volume);
      seeded.half_lengths.push_back(half_length);
    }
    int d = 0;  // next cell, x fastest
    while (d < Dim && ++cell[d] == hi[d]) {
      cell[d] = lo[d];
      ++d;
    }
    if (d == Dim) break;
  }
  return seeded;
}

template int points_per_cell<2>(const SeedingPattern&);
template int points_per_cell<3>(const SeedingPattern&);
template std::vector<Vec<2>> cell_pattern<2>(const SeedingPattern&);
template std::vector<Vec<3>> cell_pattern<3>(const SeedingPattern&);
template SeededParticles<2> seed_cells<2>(const std::function<bool(const Vec<2>&)>&, const Box<2>&,
                                          const GridGeometry<2>&, const SeedingPattern&);
template SeededParticles<3> seed_cells<3>(const std::function<bool(const Vec<3>&)>&, const Box<3>&,
                                          const GridGeometry<3>&, const SeedingPattern&);

}  // namespace mpm
