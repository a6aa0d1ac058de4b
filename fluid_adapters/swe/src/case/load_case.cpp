#include "swe/case/load_case.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "cosim/config/document.hpp"
#include "cosim/config/kind.hpp"
#include "cosim/error.hpp"
#include "cosim/io/content_hash.hpp"
#include "cosim/io/output_schedule.hpp"
#include "swe/case/case_schema.hpp"
#include "swe/case/case_size.hpp"
#include "swe/scheme.hpp"

namespace swe {

using cosim::config::Node;

namespace {

std::array<double, 2> pair_of(const Node& node, int dimension) {
  const auto v = node.as<std::vector<double>>();
  if (static_cast<int>(v.size()) != dimension)
    node.fail(
        fmt::format("expected {} value(s) for a {}D case, got {}", dimension, dimension, v.size()));
  return {v[0], v.size() > 1 ? v[1] : 0.0};
}

class CaseReader {
 public:
  explicit CaseReader(const cosim::config::Document& document)
      : document_(document), root_(document.root()) {}

  CaseDescription read() {
    cosim::config::expect_kind(root_, "swe_case");
    swe_case_schema().validate(root_);
    swe_case_schema().add_defaults(root_);
    CaseDescription c;
    c.file = document_.path();
    c.config_hash = cosim::hash_bytes(document_.text());
    c.name = root_["name"].as<std::string>();
    c.dimension = root_["dimension"].as<int>();
    read_mesh(c);
    read_physics(c);
    read_scheme(c);
    read_boundaries(c);
    read_bed(c);
    read_initial(c);
    read_time(c);
    read_output(c);
    c.threads = root_.get<int>("threads");
    read_coupling(c);
    read_two_phase(c);
    check_coupling(c);
    return c;
  }

 private:
  void read_mesh(CaseDescription& c) {
    const Node mesh = root_["mesh"];
    if (c.dimension == 1) {
      for (const char* key : {"origin", "upper"})
        if (auto n = mesh.find(key))
          n->fail_at_key(fmt::format(
              "'{}' is a 2D key; a 1D mesh takes from/to/cells, segments or edges", key));
      const bool uniform = mesh.has("cells"), stretched = mesh.has("segments"),
                 listed = mesh.has("edges");
      if (int(uniform) + int(stretched) + int(listed) != 1)
        mesh.fail("give exactly one of: `cells` (with from/to), `segments` (with from) or `edges`");
      if (listed) {
        c.edges = mesh["edges"].as<std::vector<double>>();
        for (std::size_t i = 1; i < c.edges.size(); ++i)
          if (!(c.edges[i] > c.edges[i - 1]))
            mesh["edges"].fail(
                fmt::format("cell {} has zero or negative width: edges {:.9g} -> {:.9g}", i - 1,
                            c.edges[i - 1], c.edges[i]));
        c.size = checked_size(1, static_cast<double>(c.edges.size()) - 1.0);
      } else if (uniform) {
        const Node cells = mesh["cells"];
        const int n = cells.as<int>();
        if (n < 1) cells.fail(fmt::format("the number of cells must be >= 1, got {}", n));
        const double from = mesh["from"].as<double>(), to = mesh["to"].as<double>();
        if (!(to > from))
          mesh["to"].fail(
              fmt::format("the line has zero or negative length: from {:.9g} to {:.9g}", from, to));
        c.size = checked_size(1, n);
        c.edges.resize(static_cast<std::size_t>(n) + 1);
        for (int i = 0; i <= n; ++i)
          c.edges[static_cast<std::size_t>(i)] = from + (to - from) * i / n;
      } else {
        // Every stretch's cell count first: the size is checked before an edge is made.
        struct Stretch {
          double from, to, cells;
        };
        std::vector<Stretch> stretches;
        double from = mesh["from"].as<double>(), cells = 0.0;
        for (const Node& segment : mesh["segments"].items()) {
          const double to = segment["to"].as<double>(), width = segment["width"].as<double>();
          if (!(to > from))
            segment["to"].fail(
                fmt::format("segment ends at {:.9g}, not beyond its start {:.9g}", to, from));
          stretches.push_back({from, to, std::max(1.0, std::round((to - from) / width))});
          cells += stretches.back().cells;
          from = to;
        }
        c.size = checked_size(1, cells);
        c.edges = {stretches.front().from};
        c.edges.reserve(static_cast<std::size_t>(cells) + 1);
        for (const Stretch& s : stretches) {
          const auto n = static_cast<std::int64_t>(s.cells);
          for (std::int64_t i = 1; i <= n; ++i)
            c.edges.push_back(i == n ? s.to
                                     : s.from + (s.to - s.from) * static_cast<double>(i) /
                                                    static_cast<double>(n));
        }
      }
      lower_ = {c.edges.front(), 0.0};
      upper_ = {c.edges.back(), 0.0};
    } else {
      for (const char* key : {"from", "to", "segments", "edges"})
        if (auto n = mesh.find(key))
          n->fail_at_key(
              fmt::format("'{}' is a 1D key; a 2D mesh takes origin, upper and cells", key));
      const Node cells = mesh["cells"];
      const auto counts = cells.as<std::vector<int>>();
      if (counts.size() != 2 || counts[0] < 1 || counts[1] < 1)
        cells.fail("a 2D mesh needs `cells: [nx, ny]` with whole numbers >= 1");
      const auto origin = pair_of(mesh["origin"], 2), upper = pair_of(mesh["upper"], 2);
      for (std::size_t d = 0; d < 2; ++d) {
        if (!(upper[d] > origin[d]))
          mesh["upper"].fail(
              fmt::format("upper corner {:.9g} is not above the origin {:.9g} in direction {}",
                          upper[d], origin[d], d == 0 ? "x" : "y"));
        c.grid.origin[d] = origin[d];
        c.grid.cells[d] = counts[d];
        c.grid.spacing[d] = (upper[d] - origin[d]) / counts[d];
      }
      c.size = checked_size(2, static_cast<double>(counts[0]) * static_cast<double>(counts[1]));
      lower_ = origin;
      upper_ = upper;
    }
  }

  void read_physics(CaseDescription& c) {
    const Node physics = root_["physics"];
    c.physics.gravity = physics.get<double>("gravity");
    c.physics.density = physics.get<double>("density");
    c.physics.manning = physics.get<double>("manning");
    c.physics.dry_depth = physics.get<double>("dry_depth");
  }

  void read_scheme(CaseDescription& c) {
    const Node scheme = root_["scheme"];
    c.scheme.flux = flux_from_string(scheme.get<std::string>("flux"));
    c.scheme.limiter = limiter_from_string(scheme.get<std::string>("limiter"));
    c.scheme.courant = scheme.get<double>("courant");
  }

  static Boundary boundary_of(const Node& node) {
    if (node.is_scalar())
      return {node.as<std::string>() == "wall" ? BoundaryKind::wall : BoundaryKind::transmissive,
              0.0};
    if (node.size() != 1) node.fail("give one of: inflow_discharge: <q> or fixed_depth: <h>");
    if (auto q = node.find("inflow_discharge"))
      return {BoundaryKind::inflow_discharge, q->as<double>()};
    return {BoundaryKind::fixed_depth, node["fixed_depth"].as<double>()};
  }

  void read_boundaries(CaseDescription& c) {
    const auto b = root_.find("boundaries");
    if (!b) return;
    const std::vector<std::string> own =
        c.dimension == 1 ? std::vector<std::string>{"left", "right"}
                         : std::vector<std::string>{"x_min", "x_max", "y_min", "y_max"};
    for (const auto& [key, node] : b->entries()) {
      if (std::find(own.begin(), own.end(), key) == own.end())
        node.fail_at_key(fmt::format("'{}' is not a face of a {}D case (faces: {})", key,
                                     c.dimension, fmt::join(own, ", ")));
      const Boundary boundary = boundary_of(node);
      if (key == "left") c.boundaries_1d.left = boundary;
      if (key == "right") c.boundaries_1d.right = boundary;
      if (key == "x_min") c.boundaries_2d.x_min = boundary;
      if (key == "x_max") c.boundaries_2d.x_max = boundary;
      if (key == "y_min") c.boundaries_2d.y_min = boundary;
      if (key == "y_max") c.boundaries_2d.y_max = boundary;
    }
  }

  void read_bed(CaseDescription& c) {
    const Node bed = root_["bed"];
    c.bed.base = bed.get<double>("base");
    if (auto profile = bed.find("profile")) {
      for (const Node& point : profile->items()) {
        const auto p = point.as<std::vector<double>>();
        if (!c.bed.profile.empty() && !(p[0] > c.bed.profile.back()[0]))
          point.fail(fmt::format("profile x must increase: {:.9g} follows {:.9g}", p[0],
                                 c.bed.profile.back()[0]));
        c.bed.profile.push_back({p[0], p[1]});
      }
      if (c.bed.profile.front()[0] > lower_[0] || c.bed.profile.back()[0] < upper_[0])
        profile->fail(fmt::format(
            "the profile spans x = {:.9g} .. {:.9g} but the domain spans {:.9g} .. {:.9g}; "
            "it must cover the domain",
            c.bed.profile.front()[0], c.bed.profile.back()[0], lower_[0], upper_[0]));
    }
    if (auto bumps = bed.find("bumps")) {
      for (const Node& b : bumps->items()) {
        BedBump bump;
        bump.centre = pair_of(b["centre"], c.dimension);
        bump.radius = b["radius"].as<double>();
        bump.height = b["height"].as<double>();
        if (!inside(bump.centre, c.dimension, bump.radius))
          b["centre"].fail("the bump lies entirely outside the domain");
        c.bed.bumps.push_back(bump);
      }
    }
  }

  InitialRegion water_of(const Node& node, int dimension, bool required) const {
    InitialRegion r;
    const auto surface = node.find("free_surface"), depth = node.find("depth");
    if (surface && depth) depth->fail_at_key("give `free_surface` or `depth`, not both");
    if (!surface && !depth) {
      if (required) node.fail("give the water as `free_surface: <eta>` or `depth: <h>`");
      return r;
    }
    r.free_surface = surface.has_value();
    r.level = surface ? surface->as<double>() : depth->as<double>();
    if (depth && r.level < 0.0) depth->fail(fmt::format("negative depth {:.9g} m", r.level));
    if (auto v = node.find("velocity")) r.velocity = pair_of(*v, dimension);
    return r;
  }

  void read_initial(CaseDescription& c) {
    const Node initial = root_["initial"];
    c.initial.regions.push_back(water_of(initial, c.dimension, true));
    if (auto regions = initial.find("regions")) {
      for (const Node& node : regions->items()) {
        InitialRegion r = water_of(node, c.dimension, true);
        const auto box = node.find("box"), circle = node.find("circle");
        if (bool(box) == bool(circle)) node.fail("give the region's shape as `box` or `circle`");
        if (box) {
          r.shape = InitialRegion::Shape::box;
          r.min = pair_of((*box)["min"], c.dimension);
          r.max = pair_of((*box)["max"], c.dimension);
        } else {
          if (c.dimension != 2) circle->fail_at_key("a circle needs a 2D case; use a box in 1D");
          r.shape = InitialRegion::Shape::circle;
          r.centre = pair_of((*circle)["centre"], 2);
          r.radius = (*circle)["radius"].as<double>();
        }
        c.initial.regions.push_back(r);
      }
    }
  }

  void read_time(CaseDescription& c) {
    const Node time = root_["time"];
    c.end_time = time["end_time"].as<double>();
    c.min_time_step = time.get<double>("min_time_step");
    c.max_time_step = time.get<double>("max_time_step");
    c.window = time.get<double>("window");
    if (c.window > 0.0 && c.end_time / c.window > cosim::max_output_count)
      time["window"].fail(
          fmt::format("the window {:g} s gives {:.3g} windows over the run's {:g} "
                      "s, more than {:g}; give a longer window",
                      c.window, c.end_time / c.window, c.end_time, cosim::max_output_count));
  }

  void read_output(CaseDescription& c) {
    const Node output = root_["output"];
    c.output_every = output.get<double>("every");
    c.snapshots = output.get<bool>("snapshots");
    c.gauge_every = output.get<double>("gauge_every");
    for (const char* key : {"every", "gauge_every"})
      cosim::check_output_interval(output[key], c.end_time);
    if (auto gauges = output.find("gauges")) {
      for (const Node& node : gauges->items()) {
        Gauge g;
        g.name = node["name"].as<std::string>();
        for (const Gauge& other : c.gauges)
          if (other.name == g.name)
            node["name"].fail(fmt::format("a gauge named '{}' already exists", g.name));
        std::array<double, 2> at{};
        if (c.dimension == 1) {
          if (node.has("position")) node["position"].fail_at_key("a 1D gauge takes `x`");
          at = {node["x"].as<double>(), 0.0};
        } else {
          if (node.has("x")) node["x"].fail_at_key("a 2D gauge takes `position: [x, y]`");
          at = pair_of(node["position"], 2);
        }
        if (!inside(at, c.dimension, 0.0))
          node.fail(fmt::format(
              "gauge '{}' at {} lies outside the domain [{:.9g}, {:.9g}]{}", g.name,
              c.dimension == 1 ? fmt::format("x = {:.9g}", at[0])
                               : fmt::format("({:.9g}, {:.9g})", at[0], at[1]),
              lower_[0], upper_[0],
              c.dimension == 1 ? "" : fmt::format(" x [{:.9g}, {:.9g}]", lower_[1], upper_[1])));
        g.x = at[0];
        g.y = at[1];
        c.gauges.push_back(g);
      }
    }
  }

  void read_coupling(CaseDescription& c) {
    const Node coupling = root_["coupling"];
    auto listed = [&](const char* key, const char* field) {
      const auto names = coupling.get<std::vector<std::string>>(key);
      return std::find(names.begin(), names.end(), field) != names.end();
    };
    c.coupling.reads_bed = listed("reads", "bed_elevation");
    c.coupling.writes_traction = listed("writes", "bed_traction");
    c.coupling.reads_solid_layer = listed("reads", "solid_layer");
    c.coupling.writes_impulse = listed("writes", "momentum_exchange_impulse");
    c.coupling.writes_free_surface = listed("writes", "free_surface_elevation");
    if (coupling.get<std::string>("bed_pressure") == "excess")
      c.coupling.pressure = BedPressure::excess;
  }

  // The drag's parameters, each checked by cosim::exchange::check() alone so
  // that a value out of range is refused at its own key and line.
  static cosim::exchange::GeneralisedDragParameters read_drag(const Node& drag) {
    using Parameters = cosim::exchange::GeneralisedDragParameters;
    Parameters p = quadratic_drag();
    auto checked = [](const Node& node, double Parameters::*field) {
      Parameters alone = quadratic_drag();
      alone.*field = node.as<double>();
      try {
        cosim::exchange::check(alone);
      } catch (const std::invalid_argument& e) {
        node.fail(e.what());
      }
      return alone.*field;
    };
    p.exponent = checked(drag["exponent_j"], &Parameters::exponent);
    p.reynolds_exponent = checked(drag["reynolds_exponent_M"], &Parameters::reynolds_exponent);
    p.partition_exponent = checked(drag["partition_exponent_m"], &Parameters::partition_exponent);
    p.grain_size = checked(drag["grain_size"], &Parameters::grain_size);
    p.block_size = checked(drag["block_size"], &Parameters::block_size);
    if (auto k = drag.find("smoothing_speed")) {
      Parameters alone = quadratic_drag();
      alone.smoothing_speed = k->as<double>();
      try {
        cosim::exchange::check(alone);
      } catch (const std::invalid_argument& e) {
        k->fail(e.what());
      }
      p.smoothing_speed = alone.smoothing_speed;
    }
    return p;
  }

  void read_two_phase(CaseDescription& c) {
    const auto node = root_.find("two_phase");
    if (!node) return;
    if (c.dimension != 2) node->fail_at_key("the two-phase mode needs a 2D case (dimension: 2)");
    TwoPhaseSpec spec;
    spec.parameters.drag = read_drag((*node)["drag"]);
    spec.parameters.solid_density = node->get<double>("solid_density");
    spec.parameters.fluid_viscosity = node->get<double>("fluid_viscosity");
    spec.parameters.virtual_mass = node->get<bool>("virtual_mass");
    spec.sources.rain_rate = node->get<double>("rain_rate");
    spec.sources.infiltration_rate = node->get<double>("infiltration_rate");
    const double rho_f = c.physics.density, rho_s = spec.parameters.solid_density;
    if (!(rho_s > rho_f))
      (*node)["solid_density"].fail(fmt::format(
          "the grain density {:g} kg/m^3 must exceed the fluid's (physics.density) {:g} kg/m^3",
          rho_s, rho_f));
    if (auto layer = node->find("solid_layer")) {
      InitialSolidLayer l;
      l.depth = layer->get<double>("depth");
      l.density = layer->get<double>("density");
      if (!(l.density > rho_f && l.density <= rho_s))
        (*layer)["density"].fail(fmt::format(
            "the bulk density {:g} kg/m^3 of the solids with their confined fluid must lie in "
            "(rho_f, rho_s] = ({:g}, {:g}] kg/m^3 (physics.density, two_phase.solid_density)",
            l.density, rho_f, rho_s));
      l.structured_share = layer->get<double>("structured_share");
      if (auto v = layer->find("velocity")) l.velocity = pair_of(*v, 2);
      if (auto box = layer->find("box")) {
        l.in_box = true;
        l.min = pair_of((*box)["min"], 2);
        l.max = pair_of((*box)["max"], 2);
        if (!(l.max[0] >= l.min[0] && l.max[1] >= l.min[1]))
          (*box)["max"].fail("the box's upper corner lies below its lower corner");
      }
      spec.initial_layer = l;
    }
    c.two_phase = spec;
  }

  // What the coupling reads and writes needs: the solid layer a 2D two-phase
  // case, the impulse the layer it comes from.
  void check_coupling(const CaseDescription& c) const {
    const Node coupling = root_["coupling"];
    if (c.coupling.reads_solid_layer && !c.two_phase)
      coupling["reads"].fail(
          "solid_layer needs the two-phase mode: add a `two_phase` block (dimension: 2)");
    if (c.coupling.writes_impulse && !c.coupling.reads_solid_layer)
      coupling["writes"].fail(
          "momentum_exchange_impulse is the drag on a coupled solid layer: add solid_layer to "
          "coupling.reads");
    if (c.coupling.writes_free_surface && c.dimension != 2)
      coupling["writes"].fail("free_surface_elevation needs a 2D case (dimension: 2)");
  }

  // The run's size with `cells` cells, refused above what the case's limits allow.
  cosim::RunSize checked_size(int dimension, double cells) const {
    cosim::RunSize size = run_size(dimension, cells, root_);
    cosim::check_run_size(size, root_);
    return size;
  }

  bool inside(const std::array<double, 2>& x, int dimension, double margin) const {
    for (int d = 0; d < dimension; ++d) {
      const auto k = static_cast<std::size_t>(d);
      if (x[k] < lower_[k] - margin || x[k] > upper_[k] + margin) return false;
    }
    return true;
  }

  const cosim::config::Document& document_;
  Node root_;
  std::array<double, 2> lower_{}, upper_{};
};

}  // namespace

CaseDescription load_case(const std::filesystem::path& file) {
  const auto document = cosim::config::Document::load_file(file);
  return CaseReader(document).read();
}

CaseDescription load_case_text(std::string_view text, const std::filesystem::path& name) {
  const auto document = cosim::config::Document::load_string(text, name);
  return CaseReader(document).read();
}

namespace {

// The case's bed (with the solid layer on it, two-phase) and its water over
// `cells`, set into `solver`.
void lay_case(const CaseDescription& c, const cosim::Mesh& cells, Solver& solver) {
  std::vector<double> bed(cells.size());
  for (std::size_t i = 0; i < bed.size(); ++i) {
    const cosim::Vec3 x = cells.position(i);
    bed[i] = c.bed.at(x[0], x[1]);
  }
  if (c.two_phase) {
    const SolidLayer layer = lay_solid_layer(*c.two_phase, cells);
    for (std::size_t i = 0; i < bed.size(); ++i) bed[i] += layer.depth[i];
  }
  std::vector<double> h, hu, hv;
  c.initial.lay(cells, bed, h, hu, hv);
  solver.set_bed(bed);
  solver.set_state(h, hu, hv);
}

}  // namespace

std::unique_ptr<Solver> make_solver(const CaseDescription& c) {
  std::unique_ptr<Solver> solver;
  if (c.dimension == 1)
    solver = std::make_unique<Solver1d>(c.edges, c.physics, c.scheme, c.boundaries_1d);
  else
    solver = std::make_unique<Solver2d>(c.grid, c.physics, c.scheme, c.boundaries_2d);
  lay_case(c, {"swe_cells", solver->cells()}, *solver);
  return solver;
}

std::unique_ptr<Solver> make_block_solver(const CaseDescription& c, const GridBlock& block) {
  auto solver = std::make_unique<Solver2d>(sub_grid(c.grid, block.begin, block.cells), c.physics,
                                           c.scheme, c.boundaries_2d, block.link);
  // The block's cells at their centres in the whole grid.
  const cosim::UniformGrid whole = std::get<cosim::UniformGrid>(cell_mesh(c.grid));
  cosim::CellCloud centres{.dim = 2, .centres = {}, .volumes = {}};
  for (int j = 0; j < block.cells[1]; ++j)
    for (int i = 0; i < block.cells[0]; ++i) {
      const cosim::Vec3 x = whole.position(static_cast<std::size_t>(block.begin[0] + i) +
                                           static_cast<std::size_t>(c.grid.cells[0]) *
                                               static_cast<std::size_t>(block.begin[1] + j));
      centres.centres.insert(centres.centres.end(), {x[0], x[1]});
      centres.volumes.push_back(solver->cell_size(0));
    }
  lay_case(c, {"swe_cells", centres}, *solver);
  return solver;
}

}  // namespace swe
