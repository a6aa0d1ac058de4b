#include "mpm/coupling/coupling_spec.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "mpm/coupling/field_names.hpp"

namespace mpm::coupling {

namespace {

using cosim::config::Node;
using cosim::config::Schema;

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

Schema field_list(std::vector<std::string> choices) {
  return Schema::sequence(Schema::one_of(std::move(choices)));
}

Schema exchange_grid_schema() {
  Schema s = Schema::object(
      "Porous soil <-> a fluid on the cell-centred grid 'mpm_grid' over the MPM grid "
      "(Tran et al., MPMICE, eq. 7; the coupler's implicit momentum exchange).");
  s.optional("factor", Schema::integer().range(1, 64).default_value("1"),
             "MPM cells per exchange cell in each direction.")
      .optional("writes",
                field_list({names::solid_fraction, names::solid_velocity, names::solid_bulk_density,
                            names::permeability, names::grain_size, names::solid_volume_flux,
                            names::solid_temperature, names::solid_heat_capacity})
                    .default_note("[solid_fraction, solid_velocity, solid_bulk_density, "
                                  "permeability, grain_size], and solid_temperature, "
                                  "solid_heat_capacity when the case conducts heat"),
                "Fields written per cell at every window end; the thermal ones need heat "
                "conduction. solid_volume_flux (sum of phi_i U_i) is for fluids that take the "
                "solids' displaced volume from it.")
      .optional(
          "reads",
          field_list(
              {names::pore_pressure, names::pore_pressure_force, names::impulse, names::heat})
              .default_note("[pore_pressure, momentum_exchange_impulse], and "
                            "heat_exchange_energy when the case conducts heat"),
          "Fields read; the job must send each of them (a thermal soil coupled without an "
          "energy exchange lists its reads). With pore_pressure_force the solid takes the "
          "fluid solver's pressure force per cell (split by solid volume) instead of -phi_s grad p "
          "from pore_pressure, which then only sets the points' pore pressure. "
          "heat_exchange_energy needs heat conduction and is shared over the particles by "
          "heat capacity.")
      .optional("held_density_factor", Schema::number().range(1.0, 1e100).default_value("1e30"),
                "Factor on solid_bulk_density in cells whose solid cannot take the exchange "
                "impulse (rigid bodies, held bodies, fixed faces).")
      .optional("hold_at_fixed_faces", Schema::boolean().default_value("true"),
                "Count the particles in the MPM cells along fixed grid faces as held.")
      .optional("held_bodies", Schema::sequence(Schema::string().non_empty()).default_value("[]"),
                "Bodies the exchange treats as immovable.")
      .optional("initial_pore_pressure", Schema::number().unit("Pa").default_value("0"),
                "Pore pressure until the first exchange (and standalone).");
  return s;
}

Schema surface_schema() {
  Schema s = Schema::object(
      "Seabed <-> shallow water on the cell-centred grid 'mpm_surface' over the MPM grid's "
      "horizontal extent (Zheng et al., Sec. 2-3, Algorithm 1).");
  s.required("cells", Schema::vector(1, 2), "Cells per horizontal direction (Dim - 1 entries).")
      .optional("writes", field_list({names::bed_elevation}).default_value("[bed_elevation]"),
                "Fields written per surface cell at every window end.")
      .optional("reads", field_list({names::bed_traction}).default_value("[bed_traction]"),
                "Fields read; the job must send each of them.")
      .optional("bed_bodies", Schema::sequence(Schema::string().non_empty()).default_value("[]"),
                "Bodies whose particles form the bed; empty: every body.")
      .optional("strips", Schema::integer().range(1, 64).default_value("4"),
                "3D: lines across each surface cell in y along which the envelope is averaged.");
  return s;
}

std::vector<std::string> strings_or(const Node& n, const char* key,
                                    std::vector<std::string> fallback) {
  auto child = n.find(key);
  return child ? child->as<std::vector<std::string>>() : fallback;
}

// The exchange grid's thermal fields need a case that conducts heat.
void refuse_thermal_fields(const Node& exchange_grid, const char* key) {
  const auto list = exchange_grid.find(key);
  if (!list) return;
  for (const Node& item : list->items())
    if (names::is_thermal(item.as<std::string>()))
      item.fail(
          fmt::format("{} needs a case that conducts heat (a material with specific_heat, "
                      "thermal.enabled not false)",
                      item.as<std::string>()));
}

}  // namespace

bool ExchangeGridSpec::writes_field(const std::string& f) const {
  return contains(writes, f);
}
bool ExchangeGridSpec::reads_field(const std::string& f) const {
  return contains(reads, f);
}
bool SurfaceSpec::writes_field(const std::string& f) const {
  return contains(writes, f);
}
bool SurfaceSpec::reads_field(const std::string& f) const {
  return contains(reads, f);
}

Schema coupling_schema() {
  Schema s = Schema::object(
      "Coupling of the MPM to other solvers through cosim (used when the solver is started "
      "by `cosim run`; standalone the reads keep their defaults).");
  s.optional("exchange_grid", exchange_grid_schema(), "Porous-medium exchange with a fluid.")
      .optional("surface", surface_schema(), "Bed exchange with a shallow-water solver.");
  return s;
}

CouplingSpec read_coupling(const Node& node, int dimension, bool heat_conduction) {
  const Schema schema = coupling_schema();
  schema.validate(node);
  schema.add_defaults(node);
  CouplingSpec spec;
  if (auto g = node.find("exchange_grid")) {
    if (!heat_conduction) {
      refuse_thermal_fields(*g, "writes");
      refuse_thermal_fields(*g, "reads");
    }
    std::vector<std::string> writes{names::solid_fraction, names::solid_velocity,
                                    names::solid_bulk_density, names::permeability,
                                    names::grain_size};
    std::vector<std::string> reads{names::pore_pressure, names::impulse};
    if (heat_conduction) {
      writes.insert(writes.end(), {names::solid_temperature, names::solid_heat_capacity});
      reads.push_back(names::heat);
    }
    ExchangeGridSpec e;
    e.factor = g->get<int>("factor");
    e.writes = strings_or(*g, "writes", writes);
    e.reads = strings_or(*g, "reads", reads);
    e.held_density_factor = g->get<double>("held_density_factor");
    e.hold_at_fixed_faces = g->get<bool>("hold_at_fixed_faces");
    e.held_bodies = g->get<std::vector<std::string>>("held_bodies");
    e.initial_pore_pressure = g->get<double>("initial_pore_pressure");
    spec.exchange_grid = std::move(e);
  }
  if (auto n = node.find("surface")) {
    SurfaceSpec s;
    const Node cells = (*n)["cells"];
    s.cells = cells.as<std::vector<int>>();
    for (int c : s.cells)
      if (c < 1) cells.fail(fmt::format("cell counts must be positive, got {}", c));
    if (dimension >= 2 && static_cast<int>(s.cells.size()) != dimension - 1)
      cells.fail(fmt::format("a {}D case has {} horizontal direction(s), got {} cell count(s)",
                             dimension, dimension - 1, s.cells.size()));
    s.writes = n->get<std::vector<std::string>>("writes");
    s.reads = n->get<std::vector<std::string>>("reads");
    s.bed_bodies = n->get<std::vector<std::string>>("bed_bodies");
    s.strips = n->get<int>("strips");
    spec.surface = std::move(s);
  }
  return spec;
}

}  // namespace mpm::coupling
