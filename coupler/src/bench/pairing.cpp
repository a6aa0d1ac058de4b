#include "bench/pairing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>
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

int soil_dimension(const InputFile& soil) {
  const std::string d = scalar_at(soil.root(), "dimension", "2");
  return d == "3" ? 3 : (d == "1" ? 1 : 2);
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

// A mesh of the pairing as its participant declares it for this soil and case.
YAML::Node mesh_node(const PairingMesh& mesh, int soil_dim, const InputFile& own_case) {
  std::string kind = mesh.kind;
  for (const auto& rule : mesh.kind_when) {
    const bool dimension_matches = !rule.soil_dimension || *rule.soil_dimension == soil_dim;
    const bool key_matches = rule.case_has.empty() || own_case.root()[rule.case_has].IsDefined();
    if (dimension_matches && key_matches) {
      kind = rule.kind;
      break;
    }
  }
  YAML::Node m;
  m["kind"] = kind;
  m["dim"] = mesh.dimension == MeshDimension::same_as_soil ? soil_dim : soil_dim - 1;
  m.SetStyle(YAML::EmitterStyle::Flow);
  return m;
}

YAML::Node participant(const std::string& executable, const std::string& config,
                       const PairingMesh& mesh, YAML::Node mesh_declaration,
                       const std::vector<std::string>& writes,
                       const std::vector<std::string>& reads) {
  YAML::Node p;
  p["executable"] = executable;
  p["config"] = config;
  p["meshes"][mesh.name] = mesh_declaration;
  p["writes"] = field_map(writes, mesh.name);
  p["reads"] = field_map(reads, mesh.name);
  p["writes"].SetStyle(YAML::EmitterStyle::Flow);
  p["reads"].SetStyle(YAML::EmitterStyle::Flow);
  return p;
}

bool has_key_path(const YAML::Node& node, const std::string& key_path) {
  const auto dot = key_path.find('.');
  const std::string part = key_path.substr(0, dot);
  if (!node.IsMap() || !node[part]) return false;
  return dot == std::string::npos || has_key_path(node[part], key_path.substr(dot + 1));
}

void remove_key_path(YAML::Node node, const std::string& key_path) {
  if (!node.IsMap()) return;
  const auto dot = key_path.find('.');
  if (dot == std::string::npos) {
    node.remove(key_path);
    return;
  }
  const std::string part = key_path.substr(0, dot);
  if (!std::as_const(node)[part]) return;
  remove_key_path(node[part], key_path.substr(dot + 1));
}

void set_in(InputFile& file, const std::string& role, const std::string& key_path,
            const YAML::Node& value, const BackendDescriptor& from) {
  file.apply(Override{role, key_path, value, SourceLocation{from.file.string(), 0, 0}});
}

}  // namespace

PairedJob make_paired_job(const BackendDescriptor& fluid_backend, const Scenario& scenario,
                          InputFile soil, InputFile fluid, const std::string& job_name,
                          const std::string& soil_file, const std::string& fluid_file) {
  const Coupling& c = *scenario.coupling;
  const FluidPairing& pairing = *fluid_backend.fluid_pairing;
  const BackendDescriptor& soil_backend = *c.soil_backend;
  const SoilPairing& soil_side = soil_backend.soil_pairings.at(pairing.kind);

  YAML::Node root;
  root["kind"] = "job";
  root["name"] = job_name;
  root["end_time"] = c.end_time;
  root["window"] = c.window;
  PairedJob out{InputFile::from_node(root, "job"), std::move(soil), std::move(fluid)};

  const bool momentum_exchange = pairing.momentum_exchange_solved_by.has_value();
  if (momentum_exchange && (!c.drag.IsDefined() || c.drag.IsNull()))
    throw InputError(scenario.where, "coupling.drag",
                     fmt::format("scenario '{}': the {} pairing needs a drag law", scenario.name,
                                 fluid_backend.name));
  if (!soil_side.case_requires.empty() && !has_key_path(out.soil.root(), soil_side.case_requires))
    throw InputError(SourceLocation{out.soil.source().string(), 0, 0}, soil_side.case_requires,
                     fmt::format("the {} pairing with {} needs it: {}", pairing.kind,
                                 fluid_backend.name, soil_side.case_requires_why));

  std::vector<std::string> soil_writes = soil_side.writes;
  std::vector<std::string> soil_reads = soil_side.reads;
  std::vector<std::string> fluid_writes = pairing.writes;
  std::vector<std::string> fluid_reads = pairing.reads;
  std::vector<Crossing> crossings_to_fluid = pairing.from_soil;
  // The drag law may read the soil's permeability or grain size per cell.
  if (momentum_exchange)
    for (const char* per_cell : {f::permeability.name, f::grain_size.name})
      if (c.drag[per_cell] && c.drag[per_cell].IsScalar() && c.drag[per_cell].Scalar() == "field")
        soil_writes.emplace_back(per_cell);
  for (const auto& optional : c.optional_reads) {
    if (!contains(pairing.optional_reads, optional)) continue;
    soil_writes.push_back(optional);
    fluid_reads.push_back(optional);
    crossings_to_fluid.push_back({optional});
  }
  for (const auto& x : pairing.to_soil)
    if (!contains(soil_reads, x.field)) soil_reads.push_back(x.field);

  const int dim = soil_dimension(out.soil);
  YAML::Node job = out.job.root();
  // The job's order is its start order (and MPI ranks): with a momentum
  // exchange the fluid, whose mesh hosts it, comes first, else the soil.
  const auto add_fluid = [&] {
    job["participants"][fluid_participant] =
        participant(fluid_backend.executable, fluid_file, pairing.mesh,
                    mesh_node(pairing.mesh, dim, out.fluid), fluid_writes, fluid_reads);
  };
  const auto add_soil = [&] {
    job["participants"][soil_participant] =
        participant(soil_backend.executable, soil_file, soil_side.mesh,
                    mesh_node(soil_side.mesh, dim, out.soil), soil_writes, soil_reads);
  };
  if (momentum_exchange) {
    add_fluid();
    add_soil();
  } else {
    add_soil();
    add_fluid();
  }
  const auto cross = [&](const Crossing& x, const char* from, const char* to) {
    job["exchange"].push_back(
        flow_map({{"field", x.field}, {"from", from}, {"to", to}, {"mapping", x.mapping}}));
  };
  for (const auto& x : crossings_to_fluid) cross(x, soil_participant, fluid_participant);
  for (const auto& x : pairing.to_soil) cross(x, fluid_participant, soil_participant);
  if (momentum_exchange) {
    YAML::Node exchange;
    exchange["fluid"] = fluid_participant;
    exchange["solid"] = soil_participant;
    exchange["mesh"] = std::string(fluid_participant) + "." + pairing.mesh.name;
    exchange["drag"] = YAML::Clone(c.drag);
    exchange["drag"].SetStyle(YAML::EmitterStyle::Flow);
    exchange["solved_by"] = *pairing.momentum_exchange_solved_by;
    job["momentum_exchange"] = exchange;
  }

  // A soil shared by several pairings may carry the blocks of each; this
  // pairing keeps its own.
  for (const auto& other : soil_side.case_removes) remove_key_path(out.soil.root(), other);
  set_in(out.soil, "soil", soil_side.case_block + ".writes", sequence_of(soil_writes),
         soil_backend);
  set_in(out.soil, "soil", soil_side.case_block + ".reads", sequence_of(soil_reads), soil_backend);
  for (const auto& [key, value] : pairing.case_settings)
    set_in(out.fluid, "fluid", key, value, fluid_backend);

  out.job.root()["output"]["every"] = 0;
  return out;
}

}  // namespace cosim::bench
