#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <string_view>

#include "com/transport.hpp"
#include "cosim/config/document.hpp"
#include "cosim/fields.hpp"
#include "cosim/io/content_hash.hpp"
#include "exchange/drag_law_registry.hpp"
#include "job/job.hpp"

namespace cosim::job {

namespace {

std::string names_of(const std::map<std::string, std::string>& fields) {
  std::string out;
  for (const auto& [name, mesh] : fields) out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? "none" : out;
}

MeshKind mesh_kind_from(const config::Node& node) {
  const auto s = node.as<std::string>();
  for (auto k : {MeshKind::uniform_grid, MeshKind::nonuniform_line, MeshKind::point_cloud,
                 MeshKind::cell_cloud})
    if (s == to_string(k)) return k;
  node.fail("unknown mesh kind '" + s + "'");
}

std::map<std::string, std::string> field_map(const config::Node& p, const char* key,
                                             const std::map<std::string, MeshSpec>& meshes) {
  std::map<std::string, std::string> out;
  for (const auto& [field, mesh] : p[key].entries()) {
    const auto mesh_name = mesh.as<std::string>();
    if (!meshes.count(mesh_name))
      mesh.fail(fmt::format("mesh '{}' is not among this participant's meshes", mesh_name));
    out[field] = mesh_name;
  }
  return out;
}

ParticipantSpec read_participant(const std::string& name, const config::Node& p,
                                 const std::set<std::string>& programs_starting_their_processes) {
  ParticipantSpec spec;
  spec.name = name;
  spec.where = p.key_location();
  spec.executable = p["executable"].as<std::string>();
  if (auto c = p.find("config")) spec.config = c->as_path();
  spec.args = p.get<std::vector<std::string>>("args");
  spec.ranks = p.get<int>("ranks");
  spec.ranks_where = p["ranks"].location();
  if (programs_starting_their_processes.count(
          std::filesystem::path(spec.executable).filename().string()) &&
      spec.ranks > 1) {
    spec.solver_processes = spec.ranks;
    spec.ranks = 1;
  }
  for (const auto& [mesh_name, m] : p["meshes"].entries())
    spec.meshes[mesh_name] = {mesh_kind_from(m["kind"]), m["dim"].as<int>(), m.key_location()};
  spec.writes = field_map(p, "writes", spec.meshes);
  spec.reads = field_map(p, "reads", spec.meshes);
  for (const auto& [field, mesh] : spec.reads)
    if (spec.writes.count(field))
      p["reads"][field].fail(
          fmt::format("participant '{}' both writes and reads '{}'", name, field));
  return spec;
}

MappingSpec read_mapping(const config::Node& m) {
  MappingSpec spec;
  if (m.is_scalar()) {
    spec.constraint = mapping::constraint_from_string(m.as<std::string>());
    return spec;
  }
  spec.constraint = mapping::constraint_from_string(m["constraint"].as<std::string>());
  spec.kernel = mapping::kernel_from_string(m.get<std::string>("kernel"));
  if (auto b = m.find("bounds")) {
    const auto v = b->as<std::vector<double>>();
    if (!(v[0] < v[1])) b->fail("bounds must be [lo, hi] with lo < hi");
    if (spec.constraint != mapping::Constraint::conservative)
      b->fail("bounds apply to conservative transfers (a consistent map cannot overshoot)");
    spec.bounds = std::make_pair(v[0], v[1]);
  }
  return spec;
}

// Cross-references the schema cannot see.
void check_exchanges(Job& job, const config::Node& root) {
  std::map<std::pair<std::string, std::string>, std::string> seen;  // (to, field) -> key path
  const auto items = root["exchange"].items();
  for (std::size_t i = 0; i < items.size(); ++i) {
    const config::Node& e = items[i];
    ExchangeSpec x;
    x.field = e["field"].as<std::string>();
    x.from = e["from"].as<std::string>();
    x.to = e["to"].as<std::string>();
    x.mapping = read_mapping(e["mapping"]);
    x.where = e.location();
    x.key_path = e.key_path();
    const ParticipantSpec* from = job.participant(x.from);
    const ParticipantSpec* to = job.participant(x.to);
    if (!from) e["from"].fail(fmt::format("no participant named '{}'", x.from));
    if (!to) e["to"].fail(fmt::format("no participant named '{}'", x.to));
    if (x.from == x.to) e["to"].fail("a participant cannot send a field to itself");
    auto w = from->writes.find(x.field);
    if (w == from->writes.end())
      e["field"].fail(fmt::format("participant '{}' does not write '{}' (its writes: {})", x.from,
                                  x.field, names_of(from->writes)));
    auto r = to->reads.find(x.field);
    if (r == to->reads.end())
      e["field"].fail(fmt::format("participant '{}' does not read '{}' (its reads: {})", x.to,
                                  x.field, names_of(to->reads)));
    const MeshSpec& source = from->meshes.at(w->second);
    const MeshSpec& target = to->meshes.at(r->second);
    if (source.dim != target.dim)
      e.fail(
          fmt::format("field '{}' goes from {}D mesh '{}.{}' to {}D mesh '{}.{}'; mapping needs "
                      "meshes of the same dimension",
                      x.field, source.dim, x.from, w->second, target.dim, x.to, r->second));
    auto [it, fresh] = seen.emplace(std::make_pair(x.to, x.field), e.key_path());
    if (!fresh)
      e.fail(fmt::format("'{}' of participant '{}' is already provided by {}", x.field, x.to,
                         it->second));
    job.exchanges.push_back(std::move(x));
  }
}

void check_reads_provided(const Job& job, const config::Node& root) {
  for (const auto& p : job.participants)
    for (const auto& [field, mesh] : p.reads) {
      if (job.momentum_exchange && (field == fields::momentum_exchange_impulse.name ||
                                    field == fields::drag_coefficient.name))
        continue;
      if (job.energy_exchange && field == fields::heat_exchange_energy.name) continue;
      const bool provided = std::any_of(job.exchanges.begin(), job.exchanges.end(), [&](auto& x) {
        return x.to == p.name && x.field == field;
      });
      if (!provided)
        root["participants"][p.name]["reads"][field].fail(fmt::format(
            "participant '{}' reads '{}', but no exchange entry sends it", p.name, field));
    }
}

// The participants and mesh of a fluid-solid exchange block (`fluid`,
// `solid`, `mesh: <participant>.<mesh>`), checked, and a way to demand the
// fields the exchange needs of them on meshes of the exchange's dimension.
class PhasePair {
 public:
  PhasePair(const Job& job, const config::Node& m, const char* exchange)
      : node_(m), exchange_(exchange) {
    fluid_name = m["fluid"].as<std::string>();
    solid_name = m["solid"].as<std::string>();
    fluid = job.participant(fluid_name);
    solid = job.participant(solid_name);
    if (!fluid) m["fluid"].fail(fmt::format("no participant named '{}'", fluid_name));
    if (!solid) m["solid"].fail(fmt::format("no participant named '{}'", solid_name));
    if (fluid_name == solid_name)
      m["solid"].fail("the fluid and the solid are the same participant");
    const auto mesh_key = m["mesh"].as<std::string>();
    const auto dot = mesh_key.find('.');
    if (dot == std::string::npos)
      m["mesh"].fail(fmt::format("'{}' is not <participant>.<mesh>", mesh_key));
    mesh_owner = mesh_key.substr(0, dot);
    mesh = mesh_key.substr(dot + 1);
    if (mesh_owner != fluid_name && mesh_owner != solid_name)
      m["mesh"].fail("the exchange mesh belongs to the fluid or the solid participant");
    const ParticipantSpec* owner = mesh_owner == fluid_name ? fluid : solid;
    auto exchange_mesh = owner->meshes.find(mesh);
    if (exchange_mesh == owner->meshes.end())
      m["mesh"].fail(fmt::format("participant '{}' has no mesh '{}'", mesh_owner, mesh));
    dim_ = exchange_mesh->second.dim;
  }

  void require(const ParticipantSpec& p, const std::map<std::string, std::string>& fields,
               const char* field, const char* verb) const {
    auto it = fields.find(field);
    if (it == fields.end())
      node_.fail(
          fmt::format("the {} exchange needs participant '{}' to {} '{}' (add it to "
                      "participants.{}.{}s)",
                      exchange_, p.name, verb, field, p.name, verb));
    if (p.meshes.at(it->second).dim != dim_)
      node_.fail(fmt::format("'{}' of participant '{}' is on a {}D mesh, the exchange mesh is {}D",
                             field, p.name, p.meshes.at(it->second).dim, dim_));
  }

  std::string fluid_name, solid_name, mesh_owner, mesh;
  const ParticipantSpec* fluid = nullptr;
  const ParticipantSpec* solid = nullptr;

 private:
  const config::Node& node_;
  const char* exchange_;
  int dim_ = 0;
};

MomentumExchangeSpec read_momentum_exchange(const Job& job, const config::Node& m) {
  namespace f = fields;
  const PhasePair pair(job, m, "momentum");
  MomentumExchangeSpec spec;
  spec.where = m.location();
  spec.fluid = pair.fluid_name;
  spec.solid = pair.solid_name;
  spec.mesh_owner = pair.mesh_owner;
  spec.mesh = pair.mesh;
  spec.drag = m["drag"].yaml();
  spec.solved_by =
      m.get<std::string>("solved_by") == "fluid" ? ExchangeSolver::fluid : ExchangeSolver::coupler;
  const auto law = exchange::make_drag_law(m["drag"]);
  const ParticipantSpec& fluid = *pair.fluid;
  const ParticipantSpec& solid = *pair.solid;
  for (const char* field :
       {f::solid_fraction.name, f::solid_velocity.name, f::solid_bulk_density.name})
    pair.require(solid, solid.writes, field, "write");
  if (law->cell_input() == exchange::CellInput::grain_size)
    pair.require(solid, solid.writes, f::grain_size.name, "write");
  if (law->cell_input() == exchange::CellInput::permeability)
    pair.require(solid, solid.writes, f::permeability.name, "write");
  for (const char* field : {f::fluid_velocity.name, f::fluid_bulk_density.name})
    pair.require(fluid, fluid.writes, field, "write");
  pair.require(solid, solid.reads, f::momentum_exchange_impulse.name, "read");
  if (spec.solved_by == ExchangeSolver::coupler) {
    pair.require(fluid, fluid.reads, f::momentum_exchange_impulse.name, "read");
    if (fluid.reads.count(f::drag_coefficient.name))
      m.fail(fmt::format("participant '{}' reads '{}', which only `solved_by: fluid` sends",
                         fluid.name, f::drag_coefficient.name));
  } else {
    pair.require(fluid, fluid.reads, f::drag_coefficient.name, "read");
    pair.require(fluid, fluid.writes, f::momentum_exchange_impulse.name, "write");
  }
  return spec;
}

EnergyExchangeSpec read_energy_exchange(const Job& job, const config::Node& m) {
  namespace f = fields;
  const PhasePair pair(job, m, "energy");
  EnergyExchangeSpec spec;
  spec.where = m.location();
  spec.fluid = pair.fluid_name;
  spec.solid = pair.solid_name;
  spec.mesh_owner = pair.mesh_owner;
  spec.mesh = pair.mesh;
  spec.coefficient = m["coefficient"].as<double>();
  const ParticipantSpec& fluid = *pair.fluid;
  const ParticipantSpec& solid = *pair.solid;
  for (const char* field : {f::solid_temperature.name, f::solid_heat_capacity.name})
    pair.require(solid, solid.writes, field, "write");
  for (const char* field : {f::fluid_temperature.name, f::fluid_heat_capacity.name})
    pair.require(fluid, fluid.writes, field, "write");
  pair.require(fluid, fluid.reads, f::heat_exchange_energy.name, "read");
  pair.require(solid, solid.reads, f::heat_exchange_energy.name, "read");
  return spec;
}

std::string hash_inputs(std::string_view job_text, const Job& job) {
  ContentHash h;
  h.update(job_text);
  for (const auto& p : job.participants)
    if (p.config) h.update(to_hex16(hash_file(*p.config)));
  return h.hex();
}

// The job's text with the value of every participant's `ranks` key written
// in it replaced by `_`.
std::string text_without_ranks(const std::string& text, const Job& job) {
  std::vector<std::size_t> line_starts{0};
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') line_starts.push_back(i + 1);
  std::string out = text;
  // From the last to the first, so that the earlier positions hold.
  std::vector<std::size_t> values;
  for (const auto& p : job.participants) {
    const SourceLocation& at = p.ranks_where;
    if (at.line < 1 || static_cast<std::size_t>(at.line) > line_starts.size() || at.column < 1)
      continue;
    values.push_back(line_starts[static_cast<std::size_t>(at.line - 1)] +
                     static_cast<std::size_t>(at.column - 1));
  }
  std::sort(values.rbegin(), values.rend());
  for (const std::size_t start : values) {
    std::size_t end = start;
    while (end < out.size() &&
           std::string_view(",}] \t\r\n#").find(out[end]) == std::string_view::npos)
      ++end;
    out.replace(start, end - start, "_");
  }
  return out;
}

// A name that goes into file names, command lines and messages: short, of
// letters, digits and `extra` punctuation.
void check_name(const config::Node& where, const std::string& name, std::size_t max_length,
                std::string_view extra, const char* what) {
  const bool plain = std::all_of(name.begin(), name.end(), [&](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || extra.find(c) != std::string_view::npos;
  });
  if (name.empty() || name.size() > max_length || !plain)
    where.fail(fmt::format("{} '{}' must be 1 to {} letters, digits and '{}'", what,
                           name.size() > 64 ? name.substr(0, 64) + "..." : name, max_length,
                           extra));
}

}  // namespace

const ParticipantSpec* Job::participant(const std::string& n) const {
  auto it = std::find_if(participants.begin(), participants.end(),
                         [&](const ParticipantSpec& p) { return p.name == n; });
  return it == participants.end() ? nullptr : &*it;
}

std::size_t Job::windows() const {
  return static_cast<std::size_t>(std::ceil((end_time - start_time) / window - 1e-9));
}

Job load_job(const std::filesystem::path& file,
             const std::set<std::string>& programs_starting_their_processes) {
  const config::Document doc = config::Document::load_file(file);
  const config::Node root = doc.root();
  job_schema().validate(root);
  const std::set<std::string> coupling_keys = written_coupling_keys(root);
  job_schema().add_defaults(root);

  Job job;
  job.file = file;
  job.name = root["name"].as<std::string>();
  check_name(root["name"], job.name, 100, "._-", "the job's name");
  job.start_time = root.get<double>("start_time");
  job.end_time = root["end_time"].as<double>();
  job.window = root["window"].as<double>();
  job.window_where = root["window"].location();
  const config::Node stability = root["stability_check"];
  job.stability.refuse_above = stability.get<double>("refuse_above");
  job.stability.accept_unstable = stability.get<bool>("accept_unstable");
  if (!(job.end_time > job.start_time))
    root["end_time"].fail(fmt::format("end time {} s is not after the start time {} s",
                                      job.end_time, job.start_time));
  if (job.window > job.end_time - job.start_time)
    root["window"].fail(fmt::format("window {} s is longer than the run ({} s)", job.window,
                                    job.end_time - job.start_time));
  if ((job.end_time - job.start_time) / job.window > 1e9)
    root["window"].fail("more than 1e9 coupling windows");
  job.transport =
      root.get<std::string>("transport") == "mpi" ? TransportKind::mpi : TransportKind::zmq;
  const config::Node zmq = root["zmq"];
  job.zmq.scheme = zmq.get<std::string>("scheme");
  job.zmq.host = zmq.get<std::string>("host");
  job.zmq.allow_non_loopback = zmq.get<bool>("allow_non_loopback");
  job.extrapolation = root.get<std::string>("extrapolation") == "linear"
                          ? com::Extrapolation::linear
                          : com::Extrapolation::constant;
  job.window_timeout_s = root.get<double>("window_timeout");
  const config::Node output = root["output"];
  job.output_every = output.get<double>("every");
  if (job.output_every > 0.0 && (job.end_time - job.start_time) / job.output_every > 1e6)
    output["every"].fail(
        fmt::format("{} s gives more than a million snapshots over the run", job.output_every));

  for (const auto& [name, p] : root["participants"].entries()) {
    if (name == com::coupler_peer) p.fail_at_key("'coupler' is reserved for the coupler itself");
    if (name.size() > 64 || name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTU"
                                                   "VWXYZ0123456789_-") != std::string::npos)
      p.fail_at_key(
          fmt::format("participant name '{}' must be 1 to 64 letters, digits, '_' and "
                      "'-'",
                      name.size() > 64 ? name.substr(0, 64) + "..." : name));
    job.participants.push_back(read_participant(name, p, programs_starting_their_processes));
    // Several ranks of one participant are one MPMD launch with the coupler;
    // a ZeroMQ job starts each participant as one process.
    if (job.participants.back().ranks > 1 && job.transport != TransportKind::mpi)
      p["ranks"].fail(fmt::format(
          "participant '{}' on {} ranks needs 'transport: mpi' (one MPMD launch of the coupler "
          "and every participant's ranks); the job's transport is 'zmq'",
          name, job.participants.back().ranks));
  }
  check_exchanges(job, root);
  if (auto m = root.find("momentum_exchange"); m && m->is_map())
    job.momentum_exchange = read_momentum_exchange(job, *m);
  if (auto e = root.find("energy_exchange"); e && e->is_map())
    job.energy_exchange = read_energy_exchange(job, *e);
  check_reads_provided(job, root);
  job.coupling = read_coupling(job, root["coupling"], coupling_keys);
  job.config_hash = hash_inputs(doc.text(), job);
  job.config_hash_without_ranks = hash_inputs(text_without_ranks(doc.text(), job), job);
  return job;
}

}  // namespace cosim::job
