#include "ice/case/load_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cosim/config/document.hpp"
#include "cosim/config/kind.hpp"
#include "cosim/error.hpp"
#include "cosim/io/content_hash.hpp"
#include "cosim/io/output_schedule.hpp"
#include "ice/case/case_schema.hpp"
#include "ice/case/case_size.hpp"
#include "ice/eos/eos_registry.hpp"

namespace ice {

using cosim::config::Node;

namespace {

constexpr const char* side_names[] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
constexpr const char* axis_names[] = {"x", "y", "z"};

class CaseReader {
 public:
  explicit CaseReader(const cosim::config::Document& document)
      : document_(document), root_(document.root()) {}

  CaseDescription read() {
    cosim::config::expect_kind(root_, "ice_case");
    ice_case_schema().validate(root_);
    ice_case_schema().add_defaults(root_);
    CaseDescription c;
    c.file = document_.path();
    c.config_hash = cosim::hash_bytes(document_.text());
    c.name = root_["name"].as<std::string>();
    c.dimension = root_["dimension"].as<int>();
    dimension_ = c.dimension;
    read_grid(c);
    if (auto g = root_.find("gravity")) c.gravity = vector_of(*g);
    c.end_time = root_["end_time"].as<double>();
    read_window(c);
    read_materials(c);
    c.size = run_size(dimension_, cell_count(c), static_cast<int>(c.materials.size()), root_);
    cosim::check_run_size(c.size, root_);
    read_exchange(c);
    read_initial(c);
    read_boundaries(c);
    read_numerics(c);
    read_output(c);
    c.threads = root_.get<int>("threads");
    const Node coupling = root_["coupling"];
    c.coupling.drag_in_solver = coupling.get<std::string>("drag") == "ice";
    c.coupling.minimum_porosity = coupling.get<double>("minimum_porosity");
    c.coupling.drag_viscosity = coupling.get<double>("drag_viscosity");
    if (c.coupling.drag_viscosity > 0.0) {
      for (const FluidMaterial& m : c.materials) {
        if (!(m.viscosity > 0.0)) {
          coupling["drag_viscosity"].fail(fmt::format(
              "scales each fluid's drag by its viscosity, and material '{}' has none (give it "
              "materials.{}.viscosity)",
              m.name, m.name));
        }
      }
    }
    c.coupling.heat_exchange = coupling.get<bool>("heat_exchange");
    return c;
  }

 private:
  Vector3 vector_of(const Node& node) const {
    const auto v = node.as<std::vector<double>>();
    if (static_cast<int>(v.size()) != dimension_) {
      node.fail(fmt::format("expected {} value(s) for a {}D case, got {}", dimension_, dimension_,
                            v.size()));
    }
    Vector3 x{};
    std::copy(v.begin(), v.end(), x.begin());
    return x;
  }

  void read_grid(CaseDescription& c) {
    const Node grid = root_["grid"];
    c.origin = vector_of(grid["origin"]);
    c.upper = vector_of(grid["upper"]);
    const Node cells = grid["cells"];
    const auto counts = cells.as<std::vector<double>>();
    if (static_cast<int>(counts.size()) != dimension_) {
      cells.fail(fmt::format("expected {} cell count(s) for a {}D case, got {}", dimension_,
                             dimension_, counts.size()));
    }
    for (int d = 0; d < dimension_; ++d) {
      const auto k = static_cast<std::size_t>(d);
      if (!(counts[k] >= 1.0) || counts[k] != std::floor(counts[k]) || counts[k] > 1e7) {
        cells.fail(fmt::format("cells along {} must be a whole number >= 1, got {}", axis_names[d],
                               counts[k]));
      }
      c.cells[k] = static_cast<int>(counts[k]);
      if (!(c.upper[k] > c.origin[k])) {
        grid["upper"].fail(fmt::format("upper corner {} is not above the origin {} along {}",
                                       c.upper[k], c.origin[k], axis_names[d]));
      }
    }
    // Faces, one layer more than the cells along their normal, are indexed with int too.
    for (int d = 0; d < dimension_; ++d) {
      const double faces = cell_count(c) / c.cells[static_cast<std::size_t>(d)] *
                           (c.cells[static_cast<std::size_t>(d)] + 1.0);
      if (faces > std::numeric_limits<int>::max()) {
        cells.fail(
            fmt::format("the grid has {} faces normal to {}, more than the solver's indices "
                        "hold ({})",
                        cosim::grouped(faces), axis_names[d], std::numeric_limits<int>::max()));
      }
    }
  }

  double cell_count(const CaseDescription& c) const {
    double n = 1.0;
    for (int d = 0; d < dimension_; ++d) n *= c.cells[static_cast<std::size_t>(d)];
    return n;
  }

  void read_materials(CaseDescription& c) {
    const Node materials = root_["materials"];
    const auto entries = materials.entries();
    if (entries.empty()) materials.fail("give at least one material");
    if (entries.size() > 8)
      materials.fail(fmt::format("at most 8 materials, got {}", entries.size()));
    for (const auto& [name, node] : entries) {
      FluidMaterial m;
      m.name = name;
      m.eos = make_equation_of_state(node["eos"]);
      m.viscosity = node.get<double>("viscosity");
      m.thermal_conductivity = node.get<double>("thermal_conductivity");
      c.materials.push_back(std::move(m));
    }
    c.exchange = ExchangeCoefficients::none(static_cast<int>(c.materials.size()));
  }

  int material_index(const CaseDescription& c, const Node& node) const {
    const auto name = node.as<std::string>();
    for (std::size_t m = 0; m < c.materials.size(); ++m) {
      if (c.materials[m].name == name) return static_cast<int>(m);
    }
    std::string known;
    for (const FluidMaterial& m : c.materials) known += (known.empty() ? "" : ", ") + m.name;
    node.fail(fmt::format("unknown material '{}' (materials: {})", name, known));
  }

  void read_exchange(CaseDescription& c) {
    const auto list = root_.find("exchange");
    if (!list) return;
    const auto n = c.materials.size();
    std::vector<bool> seen(n * n, false);
    for (const Node& pair : list->items()) {
      const auto names = pair["materials"].items();
      const int a = material_index(c, names[0]);
      const int b = material_index(c, names[1]);
      if (a == b) pair["materials"].fail("a material does not exchange with itself");
      const auto ab = static_cast<std::size_t>(a) * n + static_cast<std::size_t>(b);
      if (seen[ab]) pair["materials"].fail("this pair is already listed");
      seen[ab] = seen[static_cast<std::size_t>(b) * n + static_cast<std::size_t>(a)] = true;
      c.exchange.set(a, b, pair.get<double>("momentum"), pair.get<double>("heat"));
    }
  }

  void read_initial(CaseDescription& c) {
    const Node initial = root_["initial"];
    InitialDescription& i = c.initial;
    i.fill = material_index(c, initial["fill"]);
    if (auto p = initial.find("pressure"); p && p->as<std::string>() != "hydrostatic") {
      i.pressure = p->as<double>();
    }
    i.reference_pressure = initial.get<double>("reference_pressure");
    i.temperature = initial.get<double>("temperature");
    if (auto v = initial.find("velocity")) i.velocity = vector_of(*v);
    i.minimum_volume_fraction = initial.get<double>("minimum_volume_fraction");
    if (i.minimum_volume_fraction * static_cast<double>(c.materials.size()) >= 0.5) {
      initial["minimum_volume_fraction"].fail("too large for this many materials");
    }
    if (auto regions = initial.find("regions")) {
      for (const Node& node : regions->items()) i.regions.push_back(read_region(c, node));
    }
  }

  Region read_region(const CaseDescription& c, const Node& node) const {
    Region r;
    const bool box = node.has("box");
    if (box == node.has("sphere")) node.fail("give exactly one of `box` or `sphere`");
    if (box) {
      r.shape = Region::Shape::box;
      r.lower = vector_of(node["box"]["lower"]);
      r.upper = vector_of(node["box"]["upper"]);
      for (int d = 0; d < dimension_; ++d) {
        const auto k = static_cast<std::size_t>(d);
        if (!(r.upper[k] > r.lower[k])) {
          node["box"]["upper"].fail(
              fmt::format("upper corner is not above the lower one along {}", axis_names[d]));
        }
        if (r.upper[k] <= c.origin[k] || r.lower[k] >= c.upper[k]) {
          node["box"].fail(fmt::format("the box lies outside the domain along {}", axis_names[d]));
        }
      }
    } else {
      r.shape = Region::Shape::sphere;
      r.centre = vector_of(node["sphere"]["centre"]);
      r.radius = node["sphere"]["radius"].as<double>();
      for (int d = 0; d < dimension_; ++d) {
        const auto k = static_cast<std::size_t>(d);
        if (r.centre[k] + r.radius <= c.origin[k] || r.centre[k] - r.radius >= c.upper[k]) {
          node["sphere"].fail(
              fmt::format("the sphere lies outside the domain along {}", axis_names[d]));
        }
      }
    }
    r.material = material_index(c, node["fill"]);
    if (auto p = node.find("pressure")) {
      if (!c.initial.pressure)
        p->fail_at_key("the initial pressure is hydrostatic; a region cannot set its own");
      r.pressure = p->as<double>();
    }
    if (auto t = node.find("temperature")) r.temperature = t->as<double>();
    if (auto v = node.find("velocity")) r.velocity = vector_of(*v);
    return r;
  }

  void read_boundaries(CaseDescription& c) {
    c.sides.assign(static_cast<std::size_t>(2 * dimension_), SideCondition{});
    const auto boundaries = root_.find("boundaries");
    if (!boundaries) return;
    for (const auto& [key, node] : boundaries->entries()) {
      const auto* name = std::find_if(std::begin(side_names), std::end(side_names),
                                      [&](const char* s) { return key == s; });
      const auto side = static_cast<int>(name - std::begin(side_names));
      if (side >= 2 * dimension_) {
        node.fail_at_key(fmt::format("side '{}' does not exist in a {}D case", key, dimension_));
      }
      SideCondition& s = c.sides[static_cast<std::size_t>(side)];
      const std::string type =
          node.is_scalar() ? node.as<std::string>() : node["type"].as<std::string>();
      s.type = type == "wall"             ? SideType::wall
               : type == "outflow"        ? SideType::outflow
               : type == "fixed_pressure" ? SideType::fixed_pressure
                                          : SideType::inflow;
      if (node.is_scalar()) continue;
      const auto pressure = node.find("pressure");
      const auto velocity = node.find("velocity");
      if (s.type == SideType::fixed_pressure) {
        if (!pressure) node.fail("a fixed_pressure side needs `pressure`");
        s.pressure = pressure->as<double>();
      } else if (pressure) {
        pressure->fail_at_key(
            fmt::format("only a fixed_pressure side takes a pressure, not {}", type));
      }
      if (s.type == SideType::inflow) {
        if (!velocity) node.fail("an inflow side needs `velocity`");
        s.velocity = vector_of(*velocity);
      } else if (velocity) {
        velocity->fail_at_key(fmt::format("only an inflow side takes a velocity, not {}", type));
      }
      if (auto t = node.find("temperature")) s.temperature = t->as<double>();
    }
  }

  void read_numerics(CaseDescription& c) {
    const Node node = root_["numerics"];
    NumericsDescription& n = c.numerics;
    n.cfl = node.get<double>("cfl");
    n.acoustic = node.get<bool>("acoustic");
    n.initial_time_step = node.get<double>("initial_time_step");
    n.min_time_step = node.get<double>("min_time_step");
    n.max_time_step = node.get<double>("max_time_step");
    n.max_step_growth = node.get<double>("max_step_growth");
    if (n.min_time_step > n.initial_time_step) {
      node["min_time_step"].fail(
          fmt::format("is above initial_time_step = {}", n.initial_time_step));
    }
    n.limiter = limiter_from_name(node.get<std::string>("limiter"));
    const Node pressure = node["pressure"];
    n.pressure.tolerance = pressure.get<double>("tolerance");
    n.pressure.max_iterations = pressure.get<int>("max_iterations");
    read_pressure_solver(pressure, dimension_, n);
    const Node equilibration = node["equilibration"];
    n.equilibration.tolerance = equilibration.get<double>("tolerance");
    n.equilibration.max_iterations = equilibration.get<int>("max_iterations");
    if (auto t = node.find("turbulence"); t && !t->is_scalar()) {
      n.smagorinsky_constant = t->get<double>("constant");
    }
  }

  // The pressure solve's solver and preconditioner, which must belong to it.
  static void read_pressure_solver(const Node& pressure, int dimension, NumericsDescription& n) {
    using Kind = NumericsDescription::PressureSolverKind;
    // hypre's structured multigrid where the grid allows (ice_mpi_bench,
    // 1e6 cells: half BoomerAMG's time a step, on one rank and on two).
    n.petsc_preconditioner = dimension >= 2 ? "pfmg" : "boomeramg";
    if (auto solver = pressure.find("solver"))
      n.pressure_solver = solver->as<std::string>() == "petsc" ? Kind::petsc : Kind::builtin;
    if (auto options = pressure.find("petsc_options")) {
      if (n.pressure_solver == Kind::builtin)
        options->fail_at_key("petsc_options are for `solver: petsc`");
      n.petsc_options = options->as<std::string>();
    }
    const auto preconditioner = pressure.find("preconditioner");
    if (!preconditioner) return;
    const std::string name = preconditioner->as<std::string>();
    const bool petsc_only = name == "gamg" || name == "boomeramg" || name == "pfmg";
    const bool builtin_only = name == "multigrid" || name == "incomplete_cholesky";
    if (petsc_only && n.pressure_solver != Kind::petsc)
      preconditioner->fail(fmt::format("'{}' is PETSc's: it needs `solver: petsc`", name));
    if (builtin_only && n.pressure_solver == Kind::petsc)
      preconditioner->fail(fmt::format(
          "'{}' is the built-in solver's; with `solver: petsc` take pfmg, boomeramg, gamg or "
          "jacobi",
          name));
    if (name == "pfmg" && dimension == 1)
      preconditioner->fail("pfmg (hypre's structured multigrid) needs a 2D or 3D grid");
    if (n.pressure_solver == Kind::petsc || name == "jacobi") n.petsc_preconditioner = name;
    if (n.pressure_solver != Kind::petsc)
      n.pressure.preconditioner = pressure_preconditioner_from_name(name);
  }

  void read_window(CaseDescription& c) {
    c.window = root_.get<double>("window");
    if (c.window > 0.0 && c.end_time / c.window > cosim::max_output_count)
      root_["window"].fail(
          fmt::format("the window {:g} s gives {:.3g} windows over the run's {:g} "
                      "s, more than {:g}; give a longer window",
                      c.window, c.end_time / c.window, c.end_time, cosim::max_output_count));
  }

  void read_output(CaseDescription& c) {
    const Node node = root_["output"];
    c.output_every = node.get<double>("every");
    c.snapshots = node.get<bool>("snapshots");
    c.gauge_every = node.get<double>("gauge_every");
    for (const char* key : {"every", "gauge_every"})
      cosim::check_output_interval(node[key], c.end_time);
    if (auto gauges = node.find("gauges")) {
      for (const Node& g : gauges->items()) {
        GaugePoint p{g["name"].as<std::string>(), vector_of(g["point"])};
        for (int d = 0; d < dimension_; ++d) {
          const auto k = static_cast<std::size_t>(d);
          if (p.point[k] < c.origin[k] || p.point[k] > c.upper[k]) {
            g["point"].fail(
                fmt::format("gauge '{}' lies outside the domain along {}", p.name, axis_names[d]));
          }
        }
        c.gauges.push_back(std::move(p));
      }
    }
    if (auto gauges = node.find("wave_gauges")) {
      const int vertical = vertical_axis(c);
      for (const Node& g : gauges->items()) {
        if (vertical < 0)
          g.fail("a wave gauge needs gravity along an axis, which gives the vertical");
        WaveGauge w{g["name"].as<std::string>(), vector_of(g["point"]),
                    g.get<std::string>("material", "water"), vertical};
        if (std::none_of(c.materials.begin(), c.materials.end(),
                         [&](const FluidMaterial& m) { return m.name == w.material; }))
          g["material"].fail(fmt::format("no material '{}' in this case", w.material));
        for (int d = 0; d < dimension_; ++d) {
          const auto k = static_cast<std::size_t>(d);
          if (d != vertical && (w.point[k] < c.origin[k] || w.point[k] > c.upper[k]))
            g["point"].fail(fmt::format("wave gauge '{}' lies outside the domain along {}", w.name,
                                        axis_names[d]));
        }
        c.wave_gauges.push_back(std::move(w));
      }
    }
  }

  // The axis gravity lies along (its largest component), or -1 without gravity.
  int vertical_axis(const CaseDescription& c) const {
    int axis = -1;
    double largest = 0.0;
    for (int d = 0; d < dimension_; ++d) {
      const double g = std::abs(c.gravity[static_cast<std::size_t>(d)]);
      if (g > largest) {
        largest = g;
        axis = d;
      }
    }
    return axis;
  }

  const cosim::config::Document& document_;
  Node root_;
  int dimension_ = 1;
};

}  // namespace

bool Region::contains(const Vector3& point, int dimension) const {
  double distance_squared = 0.0;
  for (int d = 0; d < dimension; ++d) {
    const auto k = static_cast<std::size_t>(d);
    if (shape == Shape::box && (point[k] < lower[k] || point[k] > upper[k])) return false;
    distance_squared += (point[k] - centre[k]) * (point[k] - centre[k]);
  }
  return shape == Shape::box || distance_squared <= radius * radius;
}

CaseDescription load_case(const std::filesystem::path& file) {
  const auto document = cosim::config::Document::load_file(file);
  return CaseReader(document).read();
}

CaseDescription load_case_text(std::string_view text, const std::filesystem::path& name) {
  const auto document = cosim::config::Document::load_string(text, name);
  return CaseReader(document).read();
}

}  // namespace ice
