#include "mpm/depth_averaged/depth_averaged_particles.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace mpm {

void DepthAveragedParticles::add(const Vec<2>& x, const Vec<2>& v, double depth_, double area_,
                                 double density, int material_, const Mat<2>& edges_) {
  position.push_back(x);
  velocity.push_back(v);
  volume.push_back(depth_ * area_);
  area.push_back(area_);
  edges.push_back(edges_.isZero() ? Mat<2>(std::sqrt(area_) * Mat<2>::Identity()) : edges_);
  mass.push_back(depth_ * area_ * density);
  material.push_back(material_);
  areal_strain_rate.push_back(0.0);
  velocity_gradient.push_back(Mat<2>::Zero());
  stress.push_back(Mat<2>::Zero());
  yielded.push_back(0);
  damage.push_back(0.0);
  structured_share.push_back(1.0);
  confined_fluid.push_back(0.0);
  released_fluid.push_back(0.0);
}

std::size_t DepthAveragedParticles::seed(const Vec<2>& lower, const Vec<2>& upper,
                                         const Vec<2>& spacing, int per_cell,
                                         const std::function<double(const Vec<2>&)>& depth_at,
                                         double density, int material_, const Vec<2>& v) {
  // Gauss-Legendre points and weights on [0, 1].
  std::vector<double> points, weights;
  switch (per_cell) {
    case 2:
      points = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
      weights = {0.5, 0.5};
      break;
    case 3:
      points = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
      weights = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
      break;
    case 4: {
      const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2));
      const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
      const double wa = (18.0 + std::sqrt(30.0)) / 72.0, wb = (18.0 - std::sqrt(30.0)) / 72.0;
      points = {0.5 - 0.5 * b, 0.5 - 0.5 * a, 0.5 + 0.5 * a, 0.5 + 0.5 * b};
      weights = {wb, wa, wa, wb};
      break;
    }
    default:
      throw std::invalid_argument("points per cell and direction: 2, 3 or 4, not " +
                                  std::to_string(per_cell));
  }
  const std::size_t before = size();
  const auto cells = [&](int d) {
    return static_cast<int>(std::lround((upper[d] - lower[d]) / spacing[d]));
  };
  const double cell_area = spacing.prod();
  for (int cy = 0; cy < cells(1); ++cy)
    for (int cx = 0; cx < cells(0); ++cx)
      for (int j = 0; j < per_cell; ++j)
        for (int i = 0; i < per_cell; ++i) {
          const Vec<2> x{lower[0] + (cx + points[static_cast<std::size_t>(i)]) * spacing[0],
                         lower[1] + (cy + points[static_cast<std::size_t>(j)]) * spacing[1]};
          const double h = depth_at(x);
          const double w =
              weights[static_cast<std::size_t>(i)] * weights[static_cast<std::size_t>(j)];
          const Mat<2> lattice = (Vec<2>{spacing[0] * weights[static_cast<std::size_t>(i)],
                                         spacing[1] * weights[static_cast<std::size_t>(j)]})
                                     .asDiagonal();
          if (h > 0.0) add(x, v, h, w * cell_area, density, material_, lattice);
        }
  return size() - before;
}

std::size_t DepthAveragedParticles::split(std::size_t p, int edge) {
  const Vec<2> quarter = 0.25 * edges[p].col(edge);
  volume[p] *= 0.5;
  area[p] *= 0.5;
  mass[p] *= 0.5;
  confined_fluid[p] *= 0.5;
  released_fluid[p] *= 0.5;
  edges[p].col(edge) *= 0.5;
  position.push_back(position[p] + quarter);
  position[p] -= quarter;
  velocity.push_back(velocity[p]);
  volume.push_back(volume[p]);
  area.push_back(area[p]);
  edges.push_back(edges[p]);
  mass.push_back(mass[p]);
  material.push_back(material[p]);
  areal_strain_rate.push_back(areal_strain_rate[p]);
  velocity_gradient.push_back(velocity_gradient[p]);
  stress.push_back(stress[p]);
  yielded.push_back(yielded[p]);
  damage.push_back(damage[p]);
  structured_share.push_back(structured_share[p]);
  confined_fluid.push_back(confined_fluid[p]);
  released_fluid.push_back(released_fluid[p]);
  return size() - 1;
}

double DepthAveragedParticles::total_mass() const {
  double m = 0.0;
  for (double mp : mass) m += mp;
  return m;
}

Vec<2> DepthAveragedParticles::momentum() const {
  Vec<2> p = Vec<2>::Zero();
  for (std::size_t i = 0; i < size(); ++i) p += mass[i] * velocity[i];
  return p;
}

Vec<2> DepthAveragedParticles::centre_of_mass() const {
  Vec<2> c = Vec<2>::Zero();
  for (std::size_t i = 0; i < size(); ++i) c += mass[i] * position[i];
  return c / total_mass();
}

}  // namespace mpm
