#include "bench/backend_descriptor.hpp"

#include <fmt/format.h>

#include <set>

#include "cosim/config/document.hpp"
#include "cosim/error.hpp"

namespace cosim::bench {

namespace {

PairingMesh read_mesh(const config::Node& node) {
  PairingMesh m;
  m.name = node["name"].as<std::string>();
  m.kind = node["kind"].as<std::string>();
  m.dimension = node["dimension"].as<std::string>() == "same_as_soil"
                    ? MeshDimension::same_as_soil
                    : MeshDimension::one_below_soil;
  if (auto rules = node.find("kind_when")) {
    for (const auto& r : rules->items()) {
      PairingMesh::KindRule rule;
      if (auto d = r.find("soil_dimension")) rule.soil_dimension = d->as<int>();
      rule.case_has = r.get("case_has", "");
      if (!rule.soil_dimension && rule.case_has.empty())
        r.fail("give a condition: soil_dimension or case_has");
      rule.kind = r["kind"].as<std::string>();
      m.kind_when.push_back(std::move(rule));
    }
  }
  return m;
}

std::vector<std::string> strings(const config::Node& parent, const char* key) {
  auto node = parent.find(key);
  return node ? node->as<std::vector<std::string>>() : std::vector<std::string>{};
}

std::vector<Crossing> read_crossings(const config::Node& list) {
  std::vector<Crossing> out;
  for (const auto& c : list.items())
    out.push_back({c["field"].as<std::string>(), c.get("mapping", "consistent")});
  return out;
}

FluidPairing read_fluid_pairing(const config::Node& node) {
  FluidPairing p;
  p.kind = node["kind"].as<std::string>();
  p.mesh = read_mesh(node["mesh"]);
  p.writes = strings(node, "writes");
  p.reads = strings(node, "reads");
  p.optional_reads = strings(node, "optional_reads");
  p.from_soil = read_crossings(node["from_soil"]);
  p.to_soil = read_crossings(node["to_soil"]);
  const std::set<std::string> writes(p.writes.begin(), p.writes.end());
  const std::set<std::string> reads(p.reads.begin(), p.reads.end());
  for (const auto& c : node["to_soil"].items())
    if (!writes.count(c["field"].as<std::string>()))
      c["field"].fail("the fluid sends a field it does not write (add it to `writes`)");
  for (const auto& c : node["from_soil"].items())
    if (!reads.count(c["field"].as<std::string>()))
      c["field"].fail("the fluid receives a field it does not read (add it to `reads`)");
  if (auto m = node.find("momentum_exchange")) p.momentum_exchange_solved_by = m->as<std::string>();
  if (auto settings = node.find("case_settings"))
    for (const auto& [key, value] : settings->entries()) {
      YAML::Node copy = YAML::Clone(value.yaml());
      copy.SetStyle(YAML::EmitterStyle::Default);  // written into the case as a block
      p.case_settings.emplace_back(key, copy);
    }
  return p;
}

SoilPairing read_soil_pairing(const config::Node& node) {
  SoilPairing p;
  p.mesh = read_mesh(node["mesh"]);
  p.writes = strings(node, "writes");
  p.reads = strings(node, "reads");
  p.case_block = node["case_block"].as<std::string>();
  p.case_removes = strings(node, "case_removes");
  p.case_requires = node.get("case_requires", "");
  p.case_requires_why = node.get("case_requires_why", "");
  return p;
}

void read_outputs(const config::Node& node, BackendDescriptor& d) {
  d.snapshots = node.get("snapshots", "");
  if (auto fields = node.find("fields")) {
    for (const auto& [name, stored] : fields->entries()) {
      if (stored.is_scalar())
        d.fields[name] = {stored.as<std::string>(), 0};
      else
        d.fields[name] = {stored["dataset"].as<std::string>(), stored.get("component", 0)};
    }
  }
  if (auto front = node.find("front_field")) {
    d.front_field = front->as<std::string>();
    if (!d.fields.count(d.front_field)) front->fail("not one of the backend's `fields`");
  }
  d.gauge_file = node.get("gauge_file", "");
  if (auto columns = node.find("gauge_columns")) {
    if (d.gauge_file.empty()) columns->fail_at_key("gauge columns need a `gauge_file`");
    for (const auto& [variable, header] : columns->entries()) {
      const auto text = header.as<std::string>();
      if (text.find("{gauge}") == std::string::npos)
        header.fail("a column header names its gauge as {gauge}, e.g. `p_{gauge} [Pa]`");
      d.gauge_columns[variable] = text;
    }
  }
}

}  // namespace

BackendDescriptor load_backend_descriptor(const std::filesystem::path& file) {
  const auto doc = config::Document::load_file(file);
  const config::Node root = doc.root();
  backend_descriptor_schema().validate(root);
  BackendDescriptor d;
  d.file = file;
  d.name = root["name"].as<std::string>();
  d.about = root.get("about", "");
  d.executable = root["executable"].as<std::string>();
  d.case_kind = root.get("case_kind", "");
  d.ranks_are_solver_processes = root.get("ranks", "mpi_ranks") == "solver_processes";
  if (auto outputs = root.find("outputs")) read_outputs(*outputs, d);
  if (auto fluid = root.find("fluid_pairing")) d.fluid_pairing = read_fluid_pairing(*fluid);
  if (auto soil = root.find("soil_pairings"))
    for (const auto& [kind, side] : soil->entries())
      d.soil_pairings[kind] = read_soil_pairing(side);
  return d;
}

namespace {

[[noreturn]] void not_recorded(const BackendDescriptor& d, const std::string& what) {
  throw Error(ExitCode::bad_input, fmt::format("the {} backend does not record {} (see {})", d.name,
                                               what, d.file.string()));
}

}  // namespace

std::string BackendDescriptor::gauge_file_name() const {
  if (gauge_file.empty()) not_recorded(*this, "gauges");
  return gauge_file;
}

std::string BackendDescriptor::gauge_column(const std::string& gauge,
                                            const std::string& variable) const {
  const auto it = gauge_columns.find(variable);
  if (it == gauge_columns.end()) not_recorded(*this, "gauge variable '" + variable + "'");
  std::string header = it->second;
  for (auto at = header.find("{gauge}"); at != std::string::npos;
       at = header.find("{gauge}", at + gauge.size()))
    header.replace(at, 7, gauge);
  return header;
}

std::string BackendDescriptor::snapshot_base() const {
  if (snapshots.empty()) not_recorded(*this, "field snapshots of its own");
  return snapshots;
}

StoredField BackendDescriptor::stored_field(const std::string& field) const {
  const auto it = fields.find(field);
  if (it == fields.end()) not_recorded(*this, "the field '" + field + "'");
  return it->second;
}

}  // namespace cosim::bench
