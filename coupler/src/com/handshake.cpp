#include "com/handshake.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>

#include "cosim/error.hpp"

namespace cosim::com {

using nlohmann::json;

namespace {

// A JSON number that must be a whole number in [lo, hi]. nlohmann converts
// a float such as 1e300 to an integer type with undefined behaviour, and
// wraps a large unsigned one: neither reaches a conversion here.
long whole_number(const json& j, long lo, long hi, const char* what) {
  if (j.is_number_unsigned()) {
    const auto v = j.get<std::uint64_t>();
    if (v <= static_cast<std::uint64_t>(hi) && static_cast<long>(v) >= lo)
      return static_cast<long>(v);
  } else if (j.is_number_integer()) {
    const auto v = j.get<std::int64_t>();
    if (v >= lo && v <= hi) return static_cast<long>(v);
  }
  throw std::invalid_argument(fmt::format("{} is {}, not a whole number in [{}, {}]", what,
                                          j.dump().substr(0, 40), lo, hi));
}

json field_to_json(const FieldSpec& f) {
  json j{{"name", f.name},
         {"mesh", f.mesh},
         {"components", f.components},
         {"unit", f.unit},
         {"quantity", to_string(f.quantity)},
         {"time", to_string(f.time)},
         {"allow_nonfinite", f.allow_nonfinite}};
  if (std::isfinite(f.lower_bound)) j["lower_bound"] = f.lower_bound;
  if (std::isfinite(f.upper_bound)) j["upper_bound"] = f.upper_bound;
  if (f.optional) j["optional"] = true;
  return j;
}

FieldSpec field_from_json(const json& j) {
  FieldSpec f;
  f.name = j.at("name").get<std::string>();
  f.mesh = j.at("mesh").get<std::string>();
  f.components = static_cast<int>(whole_number(j.at("components"), 1, 9, "components"));
  f.unit = j.at("unit").get<std::string>();
  const auto q = j.at("quantity").get<std::string>();
  if (q != "intensive" && q != "extensive") throw std::invalid_argument("quantity '" + q + "'");
  f.quantity = q == "intensive" ? Quantity::intensive : Quantity::extensive;
  const auto t = j.at("time").get<std::string>();
  if (t != "state" && t != "integral") throw std::invalid_argument("time '" + t + "'");
  f.time = t == "state" ? TimeTreatment::state : TimeTreatment::integral;
  f.allow_nonfinite = j.at("allow_nonfinite").get<bool>();
  if (j.contains("lower_bound")) f.lower_bound = j["lower_bound"].get<double>();
  if (j.contains("upper_bound")) f.upper_bound = j["upper_bound"].get<double>();
  if (j.contains("optional")) f.optional = j["optional"].get<bool>();
  if (f.components < 1 || f.components > 9)
    throw std::invalid_argument(fmt::format("field '{}' has {} components", f.name, f.components));
  return f;
}

MeshKind mesh_kind_from_string(const std::string& s) {
  for (auto k : {MeshKind::uniform_grid, MeshKind::nonuniform_line, MeshKind::point_cloud,
                 MeshKind::cell_cloud})
    if (s == to_string(k)) return k;
  throw std::invalid_argument("mesh kind '" + s + "'");
}

// Geometry layout of a mesh message's float64 payload:
//   uniform_grid: count 1, components 11: location, origin[3], spacing[3], cells[3], dim
//   nonuniform_line: count = edges, components 1
//   point_cloud / cell_cloud: count = points, components dim + 1: coordinates, volume
constexpr std::uint32_t grid_record = 11;

}  // namespace

std::string to_json(const Hello& h) {
  json j{{"participant", h.participant},
         {"config_hash", h.config_hash},
         {"token", h.token},
         {"program", h.program},
         {"pid", h.pid},
         {"meshes", json::array()},
         {"writes", json::array()},
         {"reads", json::array()},
         {"repeatable", h.repeatable},
         {"checkpointable", h.checkpointable},
         {"restart_window", h.restart_window},
         {"part", h.part},
         {"parts", h.parts},
         {"partitioned", h.partitioned}};
  for (const auto& m : h.meshes)
    j["meshes"].push_back({{"name", m.name}, {"kind", to_string(m.kind)}, {"dim", m.dim}});
  for (const auto& f : h.writes) j["writes"].push_back(field_to_json(f));
  for (const auto& f : h.reads) j["reads"].push_back(field_to_json(f));
  return j.dump();
}

std::string to_json(const Welcome& w) {
  return json{{"config_hash", w.config_hash},
              {"start_time", w.start_time},
              {"end_time", w.end_time},
              {"window", w.window},
              {"extrapolation", w.extrapolation == Extrapolation::linear ? "linear" : "constant"},
              {"implicit", w.implicit},
              {"time_interpolation",
               w.time_interpolation == TimeInterpolation::linear ? "linear" : "constant"},
              {"timeout_s", w.timeout_s},
              {"sends", w.sends}}
      .dump();
}

Hello parse_hello(const std::string& text, const std::string& peer) {
  try {
    const json j = json::parse(text);
    Hello h;
    h.participant = j.at("participant").get<std::string>();
    h.config_hash = j.at("config_hash").get<std::string>();
    h.token = j.value("token", std::string());
    h.program = j.at("program").get<std::string>();
    h.pid = whole_number(j.at("pid"), 0, std::numeric_limits<int>::max(), "pid");
    for (const auto& m : j.at("meshes"))
      h.meshes.push_back({m.at("name").get<std::string>(),
                          mesh_kind_from_string(m.at("kind").get<std::string>()),
                          static_cast<int>(whole_number(m.at("dim"), 1, 3, "dim"))});
    for (const auto& f : j.at("writes")) h.writes.push_back(field_from_json(f));
    for (const auto& f : j.at("reads")) h.reads.push_back(field_from_json(f));
    h.repeatable = j.at("repeatable").get<bool>();
    h.checkpointable = j.at("checkpointable").get<bool>();
    h.restart_window = static_cast<std::uint64_t>(whole_number(
        j.at("restart_window"), 0, std::numeric_limits<std::int64_t>::max(), "restart_window"));
    if (j.contains("parts")) {
      h.parts = static_cast<int>(whole_number(j.at("parts"), 1, 1 << 24, "parts"));
      h.part = static_cast<int>(whole_number(j.at("part"), 0, h.parts - 1, "part"));
      h.partitioned = j.value("partitioned", false);
    }
    return h;
  } catch (const std::exception& e) {
    throw ProtocolError(peer, std::string("malformed hello: ") + e.what());
  }
}

Welcome parse_welcome(const std::string& text, const std::string& peer) {
  try {
    const json j = json::parse(text);
    Welcome w;
    w.config_hash = j.at("config_hash").get<std::string>();
    w.start_time = j.at("start_time").get<double>();
    w.end_time = j.at("end_time").get<double>();
    w.window = j.at("window").get<double>();
    w.extrapolation = j.at("extrapolation").get<std::string>() == "linear"
                          ? Extrapolation::linear
                          : Extrapolation::constant;
    w.implicit = j.at("implicit").get<bool>();
    w.time_interpolation = j.at("time_interpolation").get<std::string>() == "linear"
                               ? TimeInterpolation::linear
                               : TimeInterpolation::constant;
    w.timeout_s = j.at("timeout_s").get<double>();
    w.sends = j.at("sends").get<std::vector<std::string>>();
    if (!(w.window > 0.0) || !(w.end_time >= w.start_time) || !(w.timeout_s > 0.0))
      throw std::invalid_argument("impossible schedule");
    return w;
  } catch (const std::exception& e) {
    throw ProtocolError(peer, std::string("malformed welcome: ") + e.what());
  }
}

Message make_mesh_message(const std::string& job_id, const std::string& sender,
                          std::uint64_t window, double time, const Mesh& mesh) {
  std::vector<double> values;
  std::uint32_t components = 1;
  std::visit(
      [&](const auto& g) {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, UniformGrid>) {
          components = grid_record;
          values = {g.location == GridLocation::node ? 1.0 : 0.0,
                    g.origin[0],
                    g.origin[1],
                    g.origin[2],
                    g.spacing[0],
                    g.spacing[1],
                    g.spacing[2],
                    static_cast<double>(g.cells[0]),
                    static_cast<double>(g.cells[1]),
                    static_cast<double>(g.cells[2]),
                    static_cast<double>(g.dim)};
        } else if constexpr (std::is_same_v<G, NonUniformLine>) {
          values = g.edges;
        } else {
          const auto& coords = [&]() -> const std::vector<double>& {
            if constexpr (std::is_same_v<G, PointCloud>)
              return g.positions;
            else
              return g.centres;
          }();
          components = static_cast<std::uint32_t>(g.dim + 1);
          values.reserve(g.size() * components);
          for (std::size_t p = 0; p < g.size(); ++p) {
            for (int d = 0; d < g.dim; ++d) values.push_back(coords[p * g.dim + d]);
            values.push_back(g.volumes[p]);
          }
        }
      },
      mesh.geometry);
  Message m = make_field_message(job_id, sender, window, time, to_string(mesh.kind()), mesh.name,
                                 values, components);
  m.header.type = MessageType::mesh;
  return m;
}

Mesh decode_mesh_message(const Message& message, const std::string& peer) {
  validate_payload(message, peer, false);
  const Header& h = message.header;
  const std::vector<double> v = message.payload.doubles();
  Mesh mesh;
  mesh.name = h.mesh;
  try {
    const MeshKind kind = mesh_kind_from_string(h.field);
    if (kind == MeshKind::uniform_grid) {
      if (h.count != 1 || h.components != grid_record)
        throw std::invalid_argument("a uniform grid record has 11 values");
      UniformGrid g;
      g.location = v[0] != 0.0 ? GridLocation::node : GridLocation::cell;
      for (int d = 0; d < 3; ++d) {
        g.origin[d] = v[1 + d];
        g.spacing[d] = v[4 + d];
        if (v[7 + d] < 1.0 || v[7 + d] > 1e9 || v[7 + d] != std::floor(v[7 + d]))
          throw std::invalid_argument(fmt::format("cells[{}] = {}", d, v[7 + d]));
        g.cells[d] = static_cast<std::int64_t>(v[7 + d]);
      }
      if (v[10] != 1.0 && v[10] != 2.0 && v[10] != 3.0)
        throw std::invalid_argument(fmt::format("dimension {}", v[10]));
      g.dim = static_cast<int>(v[10]);
      // 1e9 cells each way would overflow the grid's size: at most 2^40
      // values, as in any message.
      double values = 1.0;
      for (int d = 0; d < g.dim; ++d)
        values *= static_cast<double>(g.extent()[static_cast<std::size_t>(d)]);
      if (values > 0x1p40) throw std::invalid_argument(fmt::format("{:g} grid values", values));
      mesh.geometry = g;
    } else if (kind == MeshKind::nonuniform_line) {
      mesh.geometry = NonUniformLine{v};
    } else {
      const int dim = static_cast<int>(h.components) - 1;
      if (dim < 1 || dim > 3) throw std::invalid_argument("cloud with bad dimension");
      std::vector<double> coords, volumes;
      coords.reserve(h.count * dim);
      volumes.reserve(h.count);
      for (std::size_t p = 0; p < h.count; ++p) {
        for (int d = 0; d < dim; ++d) coords.push_back(v[p * h.components + d]);
        volumes.push_back(v[p * h.components + dim]);
      }
      if (kind == MeshKind::point_cloud)
        mesh.geometry = PointCloud{dim, coords, volumes};
      else
        mesh.geometry = CellCloud{dim, coords, volumes};
    }
    validate(mesh);
  } catch (const std::exception& e) {
    throw ProtocolError(peer, fmt::format("malformed mesh '{}': {}", h.mesh, e.what()));
  }
  return mesh;
}

}  // namespace cosim::com
