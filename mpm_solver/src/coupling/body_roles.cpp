#include "mpm/coupling/body_roles.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "cosim/error.hpp"

namespace mpm::coupling {

namespace {

std::size_t body_index(const CaseDescription& d, const std::string& name, const char* key) {
  for (std::size_t b = 0; b < d.bodies.size(); ++b)
    if (d.bodies[b].name == name) return b;
  std::vector<std::string> known;
  for (const auto& b : d.bodies) known.push_back(b.name);
  throw cosim::InputError(d.file.string() + ": key '" + key + "': no body named '" + name +
                          "' (bodies: " + fmt::format("{}", fmt::join(known, ", ")) + ")");
}

}  // namespace

std::vector<BodyRole> body_roles(const CaseDescription& d, const CouplingSpec& spec) {
  std::vector<BodyRole> roles(d.bodies.size());
  for (std::size_t b = 0; b < d.bodies.size(); ++b) {
    roles[b].rigid = d.bodies[b].rigid.has_value();
    roles[b].porous = d.bodies[b].porous.has_value();
    roles[b].held = roles[b].rigid;
  }
  if (spec.exchange_grid)
    for (const auto& name : spec.exchange_grid->held_bodies)
      roles[body_index(d, name, "coupling.exchange_grid.held_bodies")].held = true;
  if (spec.surface && !spec.surface->bed_bodies.empty()) {
    for (auto& r : roles) r.bed = false;
    for (const auto& name : spec.surface->bed_bodies)
      roles[body_index(d, name, "coupling.surface.bed_bodies")].bed = true;
  }
  return roles;
}

template <int Dim>
std::vector<std::uint8_t> held_particles(const Particles<Dim>& particles, const Grid<Dim>& grid,
                                         const std::vector<BodyRole>& roles,
                                         const FaceConditions& faces, bool at_fixed_faces) {
  std::vector<std::uint8_t> held(particles.size(), 0);
  auto fixed = [&](int face) {
    return faces[static_cast<std::size_t>(face)].kind == FaceCondition::Kind::fixed;
  };
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (roles[particles.body[p]].held) {
      held[p] = 1;
      continue;
    }
    if (!at_fixed_faces) continue;
    const auto cell = grid.cell_of(particles.position[p]);
    for (int d = 0; d < Dim; ++d) {
      const int i = cell[static_cast<std::size_t>(d)];
      if ((i == 0 && fixed(2 * d)) ||
          (i == grid.cells[static_cast<std::size_t>(d)] - 1 && fixed(2 * d + 1)))
        held[p] = 1;
    }
  }
  return held;
}

template std::vector<std::uint8_t> held_particles<2>(const Particles<2>&, const Grid<2>&,
                                                     const std::vector<BodyRole>&,
                                                     const FaceConditions&, bool);
template std::vector<std::uint8_t> held_particles<3>(const Particles<3>&, const Grid<3>&,
                                                     const std::vector<BodyRole>&,
                                                     const FaceConditions&, bool);

}  // namespace mpm::coupling
