#include "mpm/coupling/surface_traction.hpp"

#include <algorithm>
#include <limits>

namespace mpm::coupling {

template <int Dim>
TractionTotals<Dim> surface_traction(const SurfaceGrid<Dim>& surface,
                                     std::span<const double> traction,
                                     const Particles<Dim>& particles,
                                     const std::vector<BodyRole>& roles,
                                     std::vector<Vec<Dim>>& force,
                                     const MaxOverRanks& max_over_ranks,
                                     const SumOverRanks& sum_over_ranks) {
  constexpr int up = Dim - 1;
  const std::size_t columns = surface.size();
  const auto dim = static_cast<std::size_t>(Dim);
  auto takes_traction = [&](std::size_t p) {
    const BodyRole& role = roles[particles.body[p]];
    return role.bed && !role.rigid;
  };
  auto top = [&](std::size_t p) {
    return particles.position[p][up] + particles.half_length[p][up];
  };

  std::vector<double> highest(columns, -std::numeric_limits<double>::infinity());
  std::vector<std::size_t> column(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (!takes_traction(p)) continue;
    column[p] = surface.column_of(particles.position[p]);
    highest[column[p]] = std::max(highest[column[p]], top(p));
  }
  if (max_over_ranks) max_over_ranks(highest);
  auto on_surface = [&](std::size_t p) {
    // Strictly less than one particle height below, so a regular layer under the top one is out.
    return takes_traction(p) &&
           highest[column[p]] - top(p) < 2.0 * particles.half_length[p][up] * (1.0 - 1e-9);
  };
  auto face_area = [&](std::size_t p) {
    return particles.initial_volume[p] / (2.0 * particles.half_length[p][up]);
  };

  std::vector<double> area(columns, 0.0);
  TractionTotals<Dim> totals;
  for (std::size_t p = 0; p < particles.size(); ++p)
    if (on_surface(p)) {
      area[column[p]] += face_area(p);
      ++totals.surface_particles;
    }
  if (sum_over_ranks) sum_over_ranks(area);
  // Force per unit of face area in each column.
  std::vector<Vec<Dim>> per_area(columns, Vec<Dim>::Zero());
  const double cell_area = surface.cell_area();
  for (std::size_t c = 0; c < columns; ++c) {
    const Vec<Dim> f = cell_area * Eigen::Map<const Vec<Dim>>(traction.data() + c * dim);
    totals.received += f;
    if (area[c] > 0.0)
      per_area[c] = f / area[c];
    else
      totals.unapplied += f;
  }
  force.assign(particles.size(), Vec<Dim>::Zero());
  for (std::size_t p = 0; p < particles.size(); ++p)
    if (on_surface(p)) {
      force[p] = face_area(p) * per_area[column[p]];
      totals.applied += force[p];
    }
  return totals;
}

template TractionTotals<2> surface_traction<2>(const SurfaceGrid<2>&, std::span<const double>,
                                               const Particles<2>&, const std::vector<BodyRole>&,
                                               std::vector<Vec<2>>&, const MaxOverRanks&,
                                               const SumOverRanks&);
template TractionTotals<3> surface_traction<3>(const SurfaceGrid<3>&, std::span<const double>,
                                               const Particles<3>&, const std::vector<BodyRole>&,
                                               std::vector<Vec<3>>&, const MaxOverRanks&,
                                               const SumOverRanks&);

}  // namespace mpm::coupling
