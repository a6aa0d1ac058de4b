#include "mpm/coupling/pore_pressure_force.hpp"

namespace mpm::coupling {

template <int Dim>
Vec<Dim> pore_pressure_force(const ExchangeGrid<Dim>& grid, std::span<const double> pressure,
                             Particles<Dim>& particles, const std::vector<BodyRole>& roles,
                             std::vector<Vec<Dim>>& force) {
  force.assign(particles.size(), Vec<Dim>::Zero());
  Vec<Dim> total = Vec<Dim>::Zero();
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const BodyRole& role = roles[particles.body[p]];
    double p_x = 0.0;
    Vec<Dim> grad_p = Vec<Dim>::Zero();
    grid.for_each_consistent(particles.position[p],
                             [&](std::size_t c, double w, const Vec<Dim>& dw) {
                               p_x += w * pressure[c];
                               grad_p += dw * pressure[c];
                             });
    if (role.porous) particles.pore_pressure[p] = p_x;
    if (role.rigid) continue;
    // Tran et al., MPMICE, eq. 7: -phi_s grad p over the particle's volume.
    force[p] = -(1.0 - particles.porosity[p]) * particles.volume[p] * grad_p;
    total += force[p];
  }
  return total;
}

template Vec<2> pore_pressure_force<2>(const ExchangeGrid<2>&, std::span<const double>,
                                       Particles<2>&, const std::vector<BodyRole>&,
                                       std::vector<Vec<2>>&);
template Vec<3> pore_pressure_force<3>(const ExchangeGrid<3>&, std::span<const double>,
                                       Particles<3>&, const std::vector<BodyRole>&,
                                       std::vector<Vec<3>>&);

}  // namespace mpm::coupling
