#include "ice/solver/saved_state_file.hpp"

#include <fmt/format.h>

#include <string>
#include <vector>

#include "cosim/error.hpp"

namespace ice {

namespace {

// Every array of the state that holds one value per cell, by name.
template <int Dim, class State, class Visit>
void for_each_cell_field(State& s, Visit&& visit) {
  visit("fluid.pressure", s.fluid.pressure);
  visit("fluid.porosity", s.fluid.porosity);
  for (int d = 0; d < Dim; ++d)
    visit(fmt::format("fluid.solid_velocity.{}", d), s.fluid.solid_velocity[d]);
  for (std::size_t m = 0; m < s.fluid.materials.size(); ++m) {
    auto& material = s.fluid.materials[m];
    const std::string key = fmt::format("material.{}.", m);
    visit(key + "bulk_density", material.bulk_density);
    for (int d = 0; d < Dim; ++d) visit(key + fmt::format("velocity.{}", d), material.velocity[d]);
    visit(key + "temperature", material.temperature);
    visit(key + "density", material.density);
    visit(key + "volume_fraction", material.volume_fraction);
    visit(key + "specific_volume", material.specific_volume);
  }
  for (std::size_t m = 0; m < s.kappa.size(); ++m) visit(fmt::format("kappa.{}", m), s.kappa[m]);
  visit("mixture_kappa", s.mixture_kappa);
  visit("pressure_increment", s.pressure_increment);
  visit("solid_drag", s.solid_drag);
  visit("solid_bulk_density", s.solid_bulk_density);
  for (int d = 0; d < Dim; ++d)
    visit(fmt::format("solid_exchange_velocity.{}", d), s.solid_exchange_velocity[d]);
  visit("porosity_to_displace", s.porosity_to_displace);
}

// The arrays of other lengths: face fields, per material or not (their
// normal given), and the solid's impulse (Dim values per cell; normal -1).
template <int Dim, class State, class Visit>
void for_each_other_array(State& s, Visit&& visit) {
  for (std::size_t m = 0; m < s.face_velocity.size(); ++m)
    for (int d = 0; d < Dim; ++d)
      visit(fmt::format("face_velocity.{}.{}", m, d), s.face_velocity[m][d], d);
  for (int d = 0; d < Dim; ++d) visit(fmt::format("face_pressure.{}", d), s.face_pressure[d], d);
  visit("solid_impulse", s.solid_impulse, -1);
  for (std::size_t m = 0; m < s.previous_face_velocity.size(); ++m)
    for (int d = 0; d < Dim; ++d)
      visit(fmt::format("previous_face_velocity.{}.{}", m, d), s.previous_face_velocity[m][d], d);
}

// The scalars of a state and the counts of its per-material arrays.
template <int Dim>
void read_scalars(const cosim::StateFileReader& in, SavedIceState<Dim>& s) {
  if (in.integer("dimension") != Dim)
    throw cosim::InputError(fmt::format("{}: a {}D state, the case is {}D", in.file().string(),
                                        in.integer("dimension"), Dim));
  const auto count = [&](const char* name) { return static_cast<std::size_t>(in.integer(name)); };
  s.fluid.materials.resize(count("materials"));
  s.kappa.resize(count("kappas"));
  s.face_velocity.resize(count("face_velocities"));
  s.previous_face_velocity.resize(count("previous_face_velocities"));
  s.time = in.number("time");
  s.steps = static_cast<long>(in.integer("steps"));
  s.last_face_rate = in.number("last_face_rate");
  s.solid_drag_on = in.integer("solid_drag_on") != 0;
}

// A block's faces normal to `normal` as a block of cells one longer along it.
cosim::decomposition::StoredBlock faces_of(cosim::decomposition::StoredBlock b, int normal) {
  const auto d = static_cast<std::size_t>(normal);
  ++b.owned[d].end;
  ++b.stored[d].end;
  return b;
}

}  // namespace

template <int Dim>
void write_saved_state(cosim::StateFileWriter& out, const SavedIceState<Dim>& s) {
  out.integer("dimension", Dim);
  out.integer("materials", static_cast<std::int64_t>(s.fluid.materials.size()));
  out.integer("kappas", static_cast<std::int64_t>(s.kappa.size()));
  out.integer("face_velocities", static_cast<std::int64_t>(s.face_velocity.size()));
  out.integer("previous_face_velocities",
              static_cast<std::int64_t>(s.previous_face_velocity.size()));
  out.number("time", s.time);
  out.integer("steps", s.steps);
  out.number("last_face_rate", s.last_face_rate);
  out.integer("solid_drag_on", s.solid_drag_on ? 1 : 0);
  const auto write = [&](const std::string& name, const std::vector<double>& values, int = 0) {
    out.numbers(name, values);
  };
  for_each_cell_field<Dim>(s, write);
  for_each_other_array<Dim>(s, write);
}

template <int Dim>
void read_saved_state(const cosim::StateFileReader& in, std::size_t cells, SavedIceState<Dim>& s) {
  read_scalars(in, s);
  // Cell fields not in use are empty.
  for_each_cell_field<Dim>(s, [&](const std::string& name, std::vector<double>& values) {
    values = in.numbers(name);
    if (!values.empty() && values.size() != cells)
      throw cosim::InputError(fmt::format("{}: array '{}' has {} values, the case has {} cells",
                                          in.file().string(), name, values.size(), cells));
  });
  for_each_other_array<Dim>(s, [&](const std::string& name, std::vector<double>& values, int) {
    values = in.numbers(name);
  });
}

template <int Dim>
void read_saved_state(std::span<const cosim::StateFileReader* const> parts,
                      std::span<const cosim::decomposition::StoredBlock> from,
                      const std::array<std::int64_t, 3>& grid_cells,
                      const cosim::decomposition::StoredBlock& to, SavedIceState<Dim>& s) {
  using cosim::decomposition::StoredBlock;
  read_scalars(*parts[0], s);
  // One array joined from the parts' (arrays not in use are empty in every part).
  const auto join = [&](const std::string& name, std::vector<double>& values, const auto& placed,
                        std::array<std::int64_t, 3> cells) {
    std::vector<std::vector<double>> arrays;
    std::vector<std::span<const double>> spans;
    std::vector<StoredBlock> blocks;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      arrays.push_back(parts[p]->numbers(name));
      blocks.push_back(placed(from[p]));
    }
    if (arrays[0].empty()) {
      values.clear();
      return;
    }
    for (std::size_t p = 0; p < parts.size(); ++p) {
      if (arrays[p].size() != blocks[p].size())
        throw cosim::InputError(fmt::format("{}: array '{}' has {} values, its block {}",
                                            parts[p]->file().string(), name, arrays[p].size(),
                                            blocks[p].size()));
      spans.emplace_back(arrays[p]);
    }
    const StoredBlock mine = placed(to);
    values.assign(mine.size(), 0.0);
    if (cosim::decomposition::join_blocks(blocks, spans, cells, mine, values) > 0)
      throw cosim::InputError(
          fmt::format("{} and the other parts of its checkpoint do not cover "
                      "this block's '{}'",
                      parts[0]->file().string(), name));
  };
  const auto same = [](const StoredBlock& b) { return b; };
  for_each_cell_field<Dim>(s, [&](const std::string& name, std::vector<double>& values) {
    join(name, values, same, grid_cells);
  });
  for_each_other_array<Dim>(
      s, [&](const std::string& name, std::vector<double>& values, int normal) {
        if (normal < 0) {
          join(
              name, values,
              [](StoredBlock b) {
                b.components = Dim;
                return b;
              },
              grid_cells);
          return;
        }
        std::array<std::int64_t, 3> faces = grid_cells;
        ++faces[static_cast<std::size_t>(normal)];
        join(
            name, values, [normal](const StoredBlock& b) { return faces_of(b, normal); }, faces);
      });
}

template void write_saved_state<1>(cosim::StateFileWriter&, const SavedIceState<1>&);
template void write_saved_state<2>(cosim::StateFileWriter&, const SavedIceState<2>&);
template void write_saved_state<3>(cosim::StateFileWriter&, const SavedIceState<3>&);
template void read_saved_state<1>(const cosim::StateFileReader&, std::size_t, SavedIceState<1>&);
template void read_saved_state<2>(const cosim::StateFileReader&, std::size_t, SavedIceState<2>&);
template void read_saved_state<3>(const cosim::StateFileReader&, std::size_t, SavedIceState<3>&);
template void read_saved_state<1>(std::span<const cosim::StateFileReader* const>,
                                  std::span<const cosim::decomposition::StoredBlock>,
                                  const std::array<std::int64_t, 3>&,
                                  const cosim::decomposition::StoredBlock&, SavedIceState<1>&);
template void read_saved_state<2>(std::span<const cosim::StateFileReader* const>,
                                  std::span<const cosim::decomposition::StoredBlock>,
                                  const std::array<std::int64_t, 3>&,
                                  const cosim::decomposition::StoredBlock&, SavedIceState<2>&);
template void read_saved_state<3>(std::span<const cosim::StateFileReader* const>,
                                  std::span<const cosim::decomposition::StoredBlock>,
                                  const std::array<std::int64_t, 3>&,
                                  const cosim::decomposition::StoredBlock&, SavedIceState<3>&);

}  // namespace ice
