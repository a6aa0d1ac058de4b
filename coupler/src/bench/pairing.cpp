#include "bench/pairing.hpp"

#include <fmt/format.h>

#include <vector>

#include "cosim/fields.hpp"

namespace cosim::bench {

namespace {

namespace f = fields;

YAML::Node field_map(const std::vector<std::string>& fields, const std::string& mesh) {
  YAML::Node map(YAML::NodeType::Map);
  for (const auto& f : fields) map[f] = mesh;
  return map;
}

YAML::Node sequence_of(const std::vector<std::string>& items) {
  YAML::Node seq(YAML::NodeType::Sequence);
  for (const auto& i : items) seq.push_back(i);
  return seq;
}

YAML::Node flow_map(std::initializer_list<std::pair<const char*, std::string>> entries) {
  YAML::Node map(YAML::NodeType::Map);
  for (const auto& [k, v] : entries) map[k] = v;
  map.SetStyle(YAML::EmitterStyle::Flow);
  return map;
}

YAML::Node participant(const std::string& executable, const std::string& config,
                       const std::string& mesh, const std::string& mesh_kind, int dim,
                       const std::vector<std::string>& writes,
                       const std::vector<std::string>& reads) {
  YAML::Node p;
  p["executable"] = executable;
  p["config"] = config;
  YAML::Node m;
  m["kind"] = mesh_kind;
  m["dim"] = dim;
  m.SetStyle(YAML::EmitterStyle::Flow);
  p["meshes"][mesh] = m;
  p["writes"] = field_map(writes, mesh);
  p["reads"] = field_map(reads, mesh);
  p["writes"].SetStyle(YAML::EmitterStyle::Flow);
  p["reads"].SetStyle(YAML::EmitterStyle::Flow);
  return p;
}

struct Crossing {
  std::string field;
  bool to_fluid = true;
  std::string mapping = "consistent";
};

int soil_dimension(const InputFile& soil) {
  const std::string d = scalar_at(soil.root(), "dimension", "2");
  return d == "3" ? 3 : (d == "1" ? 1 : 2);
}

void porous_pairing(Backend backend, const Scenario& s, PairedJob& out,
                    const std::string& soil_file, const std::string& fluid_file) {
  const Coupling& c = *s.coupling;
  if (!c.drag.IsDefined() || c.drag.IsNull())
    throw InputError(
        s.where, "coupling.drag",
        fmt::format("scenario '{}': the {} pairing needs a drag law", s.name, to_string(backend)));
  const bool ice = backend == Backend::ice;
  const int dim = soil_dimension(out.soil);
  std::vector<std::string> soil_writes{f::solid_fraction.name, f::solid_velocity.name,
                                       f::solid_bulk_density.name};
  for (const char* per_cell : {f::permeability.name, f::grain_size.name})
    if (c.drag[per_cell] && c.drag[per_cell].IsScalar() && c.drag[per_cell].Scalar() == "field")
      soil_writes.emplace_back(per_cell);
  std::vector<std::string> soil_reads{f::pore_pressure.name, f::momentum_exchange_impulse.name};
  std::vector<std::string> fluid_writes{f::pore_pressure.name, f::fluid_velocity.name,
                                        f::fluid_bulk_density.name,
                                        f::momentum_exchange_impulse.name};
  std::vector<std::string> fluid_reads{f::solid_fraction.name, f::solid_velocity.name,
                                       f::solid_bulk_density.name, f::drag_coefficient.name};
  std::vector<Crossing> crossings{
      {f::solid_fraction.name}, {f::solid_velocity.name}, {f::solid_bulk_density.name}};
  for (const auto& optional : c.optional_reads) {
    if (optional == f::solid_volume_flux.name && !ice) {
      soil_writes.push_back(optional);
      fluid_reads.push_back(optional);
      crossings.push_back({optional});
    }
  }
  crossings.push_back({f::pore_pressure.name, false});
  if (ice) {
    // The pressure's force on the solid in each cell, as the fluid feels the
    // same gradient (Tran et al., MPMICE, eq. 48).
    soil_reads.emplace_back(f::pore_pressure_force.name);
    fluid_writes.emplace_back(f::pore_pressure_force.name);
    crossings.push_back({f::pore_pressure_force.name, false, "conservative"});
  }

  const std::string fluid_mesh = ice ? "ice_cells" : "openfoam_cells";
  // A user's own OpenFOAM case is a cloud of cells, a generated one a grid.
  const bool cell_cloud = !ice && out.fluid.root()["directory"].IsDefined();
  YAML::Node job = out.job.root();
  job["participants"][fluid_participant] =
      participant(ice ? "ice_fluid" : "openfoam_adapter", fluid_file, fluid_mesh,
                  cell_cloud ? "cell_cloud" : "uniform_grid", dim, fluid_writes, fluid_reads);
  job["participants"][soil_participant] = participant("mpm_solver", soil_file, "mpm_grid",
                                                      "uniform_grid", dim, soil_writes, soil_reads);
  for (const auto& x : crossings) {
    job["exchange"].push_back(flow_map({{"field", x.field},
                                        {"from", x.to_fluid ? soil_participant : fluid_participant},
                                        {"to", x.to_fluid ? fluid_participant : soil_participant},
                                        {"mapping", x.mapping}}));
  }
  YAML::Node exchange;
  exchange["fluid"] = fluid_participant;
  exchange["solid"] = soil_participant;
  exchange["mesh"] = std::string(fluid_participant) + "." + fluid_mesh;
  exchange["drag"] = YAML::Clone(c.drag);
  exchange["drag"].SetStyle(YAML::EmitterStyle::Flow);
  exchange["solved_by"] = "fluid";
  job["momentum_exchange"] = exchange;

  // A soil shared by several pairings may carry the blocks of each; this
  // pairing keeps its own.
  out.soil.root()["coupling"].remove("surface");
  YAML::Node grid = out.soil.root()["coupling"]["exchange_grid"];
  grid["writes"] = sequence_of(soil_writes);
  grid["reads"] = sequence_of(soil_reads);
  if (ice) out.fluid.root()["coupling"]["drag"] = "ice";
}

void bed_pairing(PairedJob& out, const std::string& soil_file, const std::string& fluid_file) {
  const int dim = soil_dimension(out.soil);
  YAML::Node job = out.job.root();
  job["participants"][soil_participant] =
      participant("mpm_solver", soil_file, "mpm_surface", "uniform_grid", dim - 1,
                  {f::bed_elevation.name}, {f::bed_traction.name});
  job["participants"][fluid_participant] = participant(
      "swe_fluid", fluid_file, "swe_cells", dim == 2 ? "nonuniform_line" : "uniform_grid", dim - 1,
      {f::bed_traction.name}, {f::bed_elevation.name});
  job["exchange"].push_back(flow_map({{"field", f::bed_elevation.name},
                                      {"from", soil_participant},
                                      {"to", fluid_participant},
                                      {"mapping", "consistent"}}));
  job["exchange"].push_back(flow_map({{"field", f::bed_traction.name},
                                      {"from", fluid_participant},
                                      {"to", soil_participant},
                                      {"mapping", "consistent"}}));
  if (!out.soil.root()["coupling"]["surface"]["cells"])
    throw InputError(SourceLocation{out.soil.source().string(), 0, 0}, "coupling.surface.cells",
                     "the shallow-water pairing needs the soil's surface grid "
                     "(coupling: {surface: {cells: [...]}})");
  out.soil.root()["coupling"].remove("exchange_grid");
  YAML::Node surface = out.soil.root()["coupling"]["surface"];
  surface["writes"] = sequence_of({f::bed_elevation.name});
  surface["reads"] = sequence_of({f::bed_traction.name});
  YAML::Node fluid = out.fluid.root()["coupling"];
  fluid["reads"] = sequence_of({f::bed_elevation.name});
  fluid["writes"] = sequence_of({f::bed_traction.name});
}

}  // namespace

PairedJob make_paired_job(Backend backend, const Scenario& scenario, InputFile soil,
                          InputFile fluid, const std::string& job_name,
                          const std::string& soil_file, const std::string& fluid_file) {
  YAML::Node job;
  job["kind"] = "job";
  job["name"] = job_name;
  job["end_time"] = scenario.coupling->end_time;
  job["window"] = scenario.coupling->window;
  PairedJob out{InputFile::from_node(job, "job"), std::move(soil), std::move(fluid)};
  if (backend == Backend::swe)
    bed_pairing(out, soil_file, fluid_file);
  else
    porous_pairing(backend, scenario, out, soil_file, fluid_file);
  out.job.root()["output"]["every"] = 0;
  return out;
}

}  // namespace cosim::bench
