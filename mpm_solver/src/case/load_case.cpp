#include "mpm/case/load_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "case/body_seeding.hpp"
#include "case/case_size.hpp"
#include "cosim/config/closest_key.hpp"
#include "cosim/config/document.hpp"
#include "cosim/error.hpp"
#include "cosim/io/output_schedule.hpp"
#include "mpm/case/case_schema.hpp"
#include "mpm/case/velocity_history.hpp"
#include "mpm/material/material_parameters.hpp"
#include "mpm/material/material_registry.hpp"

namespace mpm {

namespace {

using cosim::config::Node;

std::string format_point(const Vec3d& x, int dimension) {
  if (dimension == 2) return fmt::format("({:.6g}, {:.6g})", x.x(), x.y());
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", x.x(), x.y(), x.z());
}

// A list of exactly `dimension` numbers.
Vec3d read_vector(const Node& node, int dimension) {
  const auto values = node.as<std::vector<double>>();
  if (values.size() != static_cast<std::size_t>(dimension))
    node.fail(fmt::format("expected {} values (dimension: {}), got {}", dimension, dimension,
                          values.size()));
  Vec3d v = Vec3d::Zero();
  for (int d = 0; d < dimension; ++d) v[d] = values[static_cast<std::size_t>(d)];
  return v;
}

// `dimension` whole numbers >= 1 (one given number applies to every direction).
std::array<int, 3> read_counts(const Node& node, int dimension, const char* what) {
  std::vector<double> values;
  if (node.is_scalar()) {
    values.assign(static_cast<std::size_t>(dimension), node.as<double>());
  } else {
    values = node.as<std::vector<double>>();
  }
  if (values.size() != static_cast<std::size_t>(dimension))
    node.fail(fmt::format("expected {} values (dimension: {}), got {}", dimension, dimension,
                          values.size()));
  std::array<int, 3> counts{1, 1, 1};
  for (std::size_t d = 0; d < values.size(); ++d) {
    const double v = values[d];
    if (v < 1.0 || v != std::floor(v) || v > 1e6)
      node.fail(fmt::format("{} must be whole numbers >= 1, got {}", what, v));
    counts[d] = static_cast<int>(v);
  }
  return counts;
}

template <class Enum>
Enum read_choice(const Node& root, std::string_view key,
                 std::initializer_list<std::pair<const char*, Enum>> choices) {
  const Node node = root[key];
  const auto text = node.as<std::string>();
  for (const auto& [name, value] : choices)
    if (text == name) return value;
  node.fail(fmt::format("unknown value '{}'", text));  // the schema refuses it first
}

int index_of(const std::vector<std::string>& names, const Node& node, const char* what) {
  const auto name = node.as<std::string>();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    node.fail(
        fmt::format("unknown {} '{}'; {}", what, name, cosim::config::suggestion(name, names)));
  return static_cast<int>(it - names.begin());
}

class CaseReader {
 public:
  explicit CaseReader(const cosim::config::Document& document) : root_(document.root()) {
    c_.file = document.path();
  }

  CaseDescription read() {
    mpm_case_schema().validate(root_);
    mpm_case_schema().add_defaults(root_);
    c_.name = root_.get<std::string>("name", c_.file.stem().string());
    dim_ = root_["dimension"].as<int>();
    c_.dimension = dim_;
    read_grid(root_["grid"]);
    c_.shape = read_choice<ShapeKind>(root_, "shape",
                                      {{"linear", ShapeKind::linear},
                                       {"gimp", ShapeKind::gimp},
                                       {"quadratic_bspline", ShapeKind::quadratic_bspline}});
    c_.scheme = read_choice<UpdateScheme>(
        root_, "scheme", {{"usl", UpdateScheme::usl}, {"musl", UpdateScheme::musl}});
    c_.flip_fraction = root_.get<double>("flip_fraction");
    c_.locking = read_choice<LockingMitigation>(root_, "locking",
                                                {{"none", LockingMitigation::none},
                                                 {"bbar", LockingMitigation::bbar},
                                                 {"fbar", LockingMitigation::fbar}});
    c_.gimp_domain = read_choice<GimpDomain>(
        root_, "gimp_domain",
        {{"initial", GimpDomain::initial}, {"deformed", GimpDomain::deformed}});
    read_time(root_["time"]);
    if (auto g = root_.find("gravity")) c_.gravity = read_vector(*g, dim_);
    c_.gravity_ramp_time = root_.get<double>("gravity_ramp_time");
    c_.damping = root_.get<double>("damping");
    if (auto materials = root_.find("materials")) read_materials(*materials);
    // The grid alone, then every body before it is seeded, must fit the limits.
    demand_ = {dim_, c_.grid, c_.shape, case_loading::velocity_fields(root_)};
    (void)checked_size(0.0);
    const Node bodies = root_["bodies"];
    for (const Node& body : bodies.items()) read_body(body);
    read_contact(root_["contact"]);
    if (auto boundaries = root_.find("boundaries")) read_boundaries(*boundaries);
    read_thermal(root_.find("thermal"));
    if (auto loads = root_.find("loads"))
      for (const Node& load : loads->items()) read_load(load);
    if (auto probes = root_.find("probes"))
      for (const Node& probe : probes->items()) read_probe(probe);
    const Node output = root_["output"];
    c_.output.every = output.get<double>("every");
    c_.output.grid = output.get<bool>("grid");
    c_.output.probe_every = output.get<double>("probe_every");
    for (const char* key : {"every", "probe_every"})
      cosim::check_output_interval(output[key], c_.time.end_time);
    c_.threads = root_.get<int>("threads");
    c_.size = checked_size(static_cast<double>(particle_count_));
    return std::move(c_);
  }

 private:
  void read_grid(const Node& grid) {
    c_.grid.origin = read_vector(grid["origin"], dim_);
    c_.grid.cells = read_counts(grid["cells"], dim_, "grid cells");
    const auto upper = grid.find("upper");
    const auto spacing = grid.find("spacing");
    if (upper.has_value() == spacing.has_value())
      grid.fail("give exactly one of `upper` and `spacing`");
    if (spacing) {
      c_.grid.spacing = read_vector(*spacing, dim_);
      for (int d = 0; d < dim_; ++d)
        if (!(c_.grid.spacing[d] > 0.0)) spacing->fail("spacing must be > 0 in every direction");
    } else {
      const Vec3d top = read_vector(*upper, dim_);
      for (int d = 0; d < dim_; ++d) {
        if (!(top[d] > c_.grid.origin[d]))
          upper->fail("upper must exceed origin in every direction");
        c_.grid.spacing[d] =
            (top[d] - c_.grid.origin[d]) / c_.grid.cells[static_cast<std::size_t>(d)];
      }
    }
    if (dim_ == 2) {
      c_.grid.origin.z() = 0.0;
      c_.grid.spacing.z() = 1.0;
      c_.grid.cells[2] = 1;
    }
  }

  void read_time(const Node& time) {
    c_.time.end_time = time["end_time"].as<double>();
    c_.time.safety_factor = time.get<double>("safety_factor");
    c_.time.min_time_step = time.get<double>("min_time_step");
    c_.time.max_time_step =
        time.get<double>("max_time_step", std::numeric_limits<double>::infinity());
    c_.time.window = time.get<double>("window", 0.0);
    if (c_.time.min_time_step > c_.time.max_time_step)
      time["min_time_step"].fail("min_time_step exceeds max_time_step");
  }

  void read_materials(const Node& materials) {
    for (const auto& [name, node] : materials.entries()) {
      c_.materials.push_back(make_material(node));
      c_.material_names.push_back(name);
    }
  }

  bool inside_grid(const Vec3d& x) const {
    for (int d = 0; d < dim_; ++d) {
      const double lo = c_.grid.origin[d];
      const double hi = lo + c_.grid.spacing[d] * c_.grid.cells[static_cast<std::size_t>(d)];
      if (!(x[d] >= lo && x[d] <= hi)) return false;
    }
    return true;
  }

  void read_body(const Node& node) {
    BodySpec body;
    const Node name = node["name"];
    body.name = name.as<std::string>();
    if (std::find(body_names_.begin(), body_names_.end(), body.name) != body_names_.end())
      name.fail(fmt::format("a body named '{}' exists already", body.name));

    const auto material = node.find("material");
    const auto rigid = node.find("rigid");
    if (material.has_value() == rigid.has_value())
      node.fail(fmt::format("body '{}' needs exactly one of `material` and `rigid`", body.name));
    if (material) {
      body.material = index_of(c_.material_names, *material, "material");
      if (auto density = node.find("density"))
        density->fail_at_key("a deformable body takes its density from its material");
      for (const char* key : {"specific_heat", "thermal_conductivity"})
        if (auto thermal = node.find(key))
          thermal->fail_at_key(
              fmt::format("a deformable body takes its {} from its material", key));
    } else {
      body.rigid = read_rigid(*rigid);
      const auto density = node.find("density");
      if (!density) node.fail(fmt::format("rigid body '{}' needs a `density`", body.name));
      body.density_override = density->as<double>();
      body.thermal_override = material_parameters::read_thermal_properties(node);
      if (auto geostatic = node.find("geostatic"))
        geostatic->fail_at_key("a rigid body has no geostatic stress");
    }

    const Node ppc_node = node["particles_per_cell"];
    const std::array<int, 3> ppc = read_counts(ppc_node, dim_, "particles_per_cell");
    const auto seeding = read_choice<case_loading::Seeding>(
        node, "seeding",
        {{"regular", case_loading::Seeding::regular}, {"r2", case_loading::Seeding::r2}});
    const Node geometry = node["geometry"];
    if (geometry.size() != 1)
      geometry.fail("give exactly one of `box`, `polygon`, `polyhedron` and `points`");
    auto seeded =
        case_loading::seed_body(geometry, dim_, c_.grid, ppc, seeding, [&](double estimate) {
          (void)checked_size(static_cast<double>(particle_count_) + estimate);
          check_seeding_counts(ppc_node, ppc);
        });
    if (seeded.positions.empty())
      geometry.fail(fmt::format(
          "body '{}' seeds no particles (region smaller than the particle spacing?)", body.name));
    for (const Vec3d& x : seeded.positions)
      if (!inside_grid(x))
        geometry.fail(fmt::format("body '{}' has particles outside the grid, the first at {}",
                                  body.name, format_point(x, dim_)));
    body.positions = std::move(seeded.positions);
    body.volumes = std::move(seeded.volumes);
    body.half_lengths = std::move(seeded.half_lengths);

    if (auto v = node.find("initial_velocity")) body.initial_velocity = read_vector(*v, dim_);
    body.initial_temperature = node.get<double>("temperature");
    if (auto porous = node.find("porous")) body.porous = read_porous(*porous);
    if (auto geostatic = node.find("geostatic")) {
      GeostaticStress g;
      g.k0 = geostatic->get<double>("k0", g.k0);
      g.unit_weight = geostatic->get<double>("unit_weight", g.unit_weight);
      if (auto surface = geostatic->find("surface")) g.surface = surface->as<double>();
      body.geostatic = g;
    }
    body_names_.push_back(body.name);
    body_offsets_.push_back(particle_count_);
    particle_count_ += body.positions.size();
    c_.bodies.push_back(std::move(body));
  }

  RigidMotion read_rigid(const Node& rigid) {
    RigidMotion motion;
    motion.kind = read_choice<RigidMotion::Kind>(rigid, "motion",
                                                 {{"fixed", RigidMotion::Kind::fixed},
                                                  {"prescribed", RigidMotion::Kind::prescribed},
                                                  {"free", RigidMotion::Kind::free}});
    const auto history = rigid.find("velocity_history");
    if (motion.kind == RigidMotion::Kind::prescribed) {
      if (!history) rigid.fail("motion: prescribed needs a `velocity_history`");
      motion.velocity = read_velocity_history(history->as_path(), dim_, *history);
    } else if (history) {
      history->fail_at_key("a velocity_history needs motion: prescribed");
    }
    return motion;
  }

  PorousSpec read_porous(const Node& porous) {
    PorousSpec p;
    p.porosity = porous["porosity"].as<double>();
    p.grain_size = porous.get<double>("grain_size", 0.0);
    p.max_porosity = porous.get<double>("max_porosity");
    if (p.porosity > p.max_porosity)
      porous["porosity"].fail(
          fmt::format("porosity {} exceeds max_porosity {}", p.porosity, p.max_porosity));
    if (auto permeability = porous.find("permeability")) {
      p.permeability_model = read_choice<PermeabilityModel>(
          *permeability, "model",
          {{"kozeny_carman_pan", PermeabilityModel::kozeny_carman_pan},
           {"kozeny_carman_tran", PermeabilityModel::kozeny_carman_tran},
           {"constant", PermeabilityModel::constant}});
      const auto value = permeability->find("value");
      if (p.permeability_model == PermeabilityModel::constant) {
        if (!value) permeability->fail("model: constant needs a `value` [m^2]");
        p.permeability = value->as<double>();
      } else if (value) {
        value->fail_at_key("`value` is only for model: constant");
      }
    }
    if (p.permeability_model != PermeabilityModel::constant && !(p.grain_size > 0.0))
      porous.fail("a Kozeny-Carman permeability needs `grain_size` [m]");
    return p;
  }

  void read_contact(const Node& contact) {
    c_.contact.enabled = contact.get<bool>("enabled");
    c_.contact.friction = contact.get<double>("friction");
    if (auto pairs = contact.find("pairs")) {
      for (const Node& pair : pairs->items()) {
        const auto bodies = pair["bodies"].items();
        const int a = index_of(body_names_, bodies[0], "body");
        const int b = index_of(body_names_, bodies[1], "body");
        if (a == b) pair["bodies"].fail("a contact pair needs two different bodies");
        c_.contact.pair_friction[{std::min(a, b), std::max(a, b)}] = pair["friction"].as<double>();
      }
    }
  }

  static int face_index(const std::string& face) {
    static const char* const names[] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
    for (int f = 0; f < 6; ++f)
      if (face == names[f]) return f;
    return -1;
  }

  void read_boundaries(const Node& boundaries) {
    for (const auto& [face, node] : boundaries.entries()) {
      const int f = face_index(face);
      if (dim_ == 2 && f >= 4) node.fail_at_key("a 2D case has no z faces");
      FaceCondition condition;
      if (node.is_map()) {
        condition.kind = FaceCondition::Kind::frictional;
        condition.friction = node["frictional"].as<double>();
      } else {
        const auto kind = node.as<std::string>();
        condition.kind = kind == "fixed"  ? FaceCondition::Kind::fixed
                         : kind == "slip" ? FaceCondition::Kind::slip
                                          : FaceCondition::Kind::free;
      }
      c_.boundaries[static_cast<std::size_t>(f)] = condition;
    }
  }

  // After the bodies: heat conduction is on when a body is thermal, unless
  // `enabled` says otherwise.
  void read_thermal(const std::optional<Node>& thermal) {
    const bool thermal_body = has_thermal_body(c_);
    c_.thermal.enabled = thermal_body;
    if (!thermal) return;
    if (auto enabled = thermal->find("enabled")) {
      c_.thermal.enabled = enabled->as<bool>();
      if (c_.thermal.enabled && !thermal_body)
        enabled->fail("no body is thermal: give a material (or a rigid body) a `specific_heat`");
    }
    for (const auto& [face, node] : thermal->entries()) {
      const int f = face_index(face);
      if (f < 0) continue;  // `enabled`
      if (dim_ == 2 && f >= 4) node.fail_at_key("a 2D case has no z faces");
      FaceTemperature& condition = c_.thermal.faces[static_cast<std::size_t>(f)];
      const auto temperature = node.find("temperature");
      if (node["type"].as<std::string>() == "fixed_temperature") {
        if (!temperature) node.fail("type: fixed_temperature needs a `temperature` [K]");
        condition.kind = FaceTemperature::Kind::fixed;
        condition.temperature = temperature->as<double>();
      } else if (temperature) {
        temperature->fail_at_key("an insulated face has no temperature");
      }
    }
  }

  std::pair<std::size_t, std::size_t> particle_range(int body) const {
    const auto b = static_cast<std::size_t>(body);
    return {body_offsets_[b], body_offsets_[b] + c_.bodies[b].positions.size()};
  }

  void read_load(const Node& node) {
    LoadSpec load;
    load.name = node["name"].as<std::string>();
    const int body = index_of(body_names_, node["body"], "body");
    const Node region = node["region"];
    const Vec3d lo = read_vector(region["min"], dim_);
    const Vec3d hi = read_vector(region["max"], dim_);
    const auto& spec = c_.bodies[static_cast<std::size_t>(body)];
    const auto [first, last] = particle_range(body);
    for (std::size_t p = first; p < last; ++p) {
      const Vec3d& x = spec.positions[p - first];
      bool inside = true;
      for (int d = 0; d < dim_; ++d) inside = inside && x[d] >= lo[d] && x[d] <= hi[d];
      if (inside) load.particles.push_back(p);
    }
    if (load.particles.empty())
      region.fail(fmt::format("load '{}' selects no particle of body '{}'", load.name, spec.name));
    load.face = face_index(node.get<std::string>("face"));
    if (dim_ == 2 && load.face >= 4) node["face"].fail("a 2D case has no z faces");
    const auto traction = node.find("traction");
    const auto pressure = node.find("pressure");
    if (traction.has_value() == pressure.has_value())
      node.fail(fmt::format("load '{}' needs exactly one of `traction` and `pressure`", load.name));
    if (traction) load.traction = read_vector(*traction, dim_);
    if (pressure) load.pressure = pressure->as<double>();
    load.ramp_time = node.get<double>("ramp_time");
    if (node.get<std::string>("ramp_shape") == "cycloidal")
      load.ramp_shape = LoadSpec::RampShape::cycloidal;
    c_.loads.push_back(std::move(load));
  }

  void read_probe(const Node& node) {
    ProbeSpec probe;
    probe.name = node["name"].as<std::string>();
    for (const auto& other : c_.probes)
      if (other.name == probe.name)
        node["name"].fail(fmt::format("a probe named '{}' exists already", probe.name));
    probe.body = index_of(body_names_, node["body"], "body");
    const Node position = node["position"];
    probe.position = read_vector(position, dim_);
    const auto& spec = c_.bodies[static_cast<std::size_t>(probe.body)];
    const auto [first, last] = particle_range(probe.body);
    std::size_t nearest = first;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t p = first; p < last; ++p) {
      const double distance = (spec.positions[p - first] - probe.position).squaredNorm();
      if (distance < best) {
        best = distance;
        nearest = p;
      }
    }
    // Inside the body: within the (slightly enlarged) domain of its nearest particle.
    const Vec3d offset = spec.positions[nearest - first] - probe.position;
    const Vec3d& h = spec.half_lengths[nearest - first];
    for (int d = 0; d < dim_; ++d)
      if (std::abs(offset[d]) > 1.5 * h[d] + 1e-12)
        position.fail(fmt::format("probe '{}' at {} is outside body '{}' (nearest particle at {})",
                                  probe.name, format_point(probe.position, dim_), spec.name,
                                  format_point(spec.positions[nearest - first], dim_)));
    probe.particle = nearest;
    c_.probes.push_back(std::move(probe));
  }

  // The seeding counts a cell's points, and the cells of the grid refined by
  // unequal counts per direction, with int.
  void check_seeding_counts(const Node& node, const std::array<int, 3>& ppc) const {
    constexpr double most = std::numeric_limits<int>::max();
    const bool refined = ppc[1] != ppc[0] || (dim_ == 3 && ppc[2] != ppc[0]);
    double per_cell = 1.0;
    for (int d = 0; d < dim_; ++d) {
      const auto k = static_cast<std::size_t>(d);
      per_cell *= ppc[k];
      if (refined && static_cast<double>(ppc[k]) * c_.grid.cells[k] > most)
        node.fail(
            fmt::format("{} particles per cell along {} grid cells make more seeding cells "
                        "than its counters hold ({})",
                        ppc[k], c_.grid.cells[k], cosim::grouped(most)));
    }
    if (per_cell > most)
      node.fail(fmt::format("{} particles per cell, more than the seeding's counters hold ({})",
                            cosim::grouped(per_cell), cosim::grouped(most)));
  }

  // The run's size with `particles`, refused above what the case's limits allow.
  cosim::RunSize checked_size(double particles) const {
    cosim::RunSize size = case_loading::run_size(demand_, particles, root_);
    cosim::check_run_size(size, root_);
    return size;
  }

  Node root_;
  CaseDescription c_;
  case_loading::GridDemand demand_;
  int dim_ = 2;
  std::vector<std::string> body_names_;
  std::vector<std::size_t> body_offsets_;
  std::size_t particle_count_ = 0;
};

}  // namespace

CaseDescription load_case(const std::filesystem::path& file) {
  return CaseReader(cosim::config::Document::load_file(file)).read();
}

CaseDescription load_case_text(std::string_view text, const std::filesystem::path& name) {
  return CaseReader(cosim::config::Document::load_string(text, name)).read();
}

}  // namespace mpm
