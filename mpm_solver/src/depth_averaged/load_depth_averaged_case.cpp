#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

#include "cosim/config/closest_key.hpp"
#include "cosim/config/document.hpp"
#include "cosim/config/kind.hpp"
#include "cosim/error.hpp"
#include "cosim/io/content_hash.hpp"
#include "cosim/io/output_schedule.hpp"
#include "mpm/depth_averaged/depth_averaged_case.hpp"
#include "mpm/depth_averaged/raster_grid.hpp"
#include "mpm/geometry/polygon.hpp"

namespace mpm {

using cosim::config::Node;

namespace {

constexpr double deg = std::numbers::pi / 180.0;

// Memory per item, an estimate from the arrays each holds (the points' 20
// doubles and their share of the snapshot buffers; a node's 10 doubles).
constexpr double bytes_per_point = 400.0;
constexpr double bytes_per_node = 120.0;
constexpr double program_bytes = 21e6;
constexpr double most_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());

Vec<2> point_of(const Node& node) {
  const auto v = node.as<std::vector<double>>();
  return {v[0], v[1]};
}

bool covers(const RasterGrid& raster, const Vec<2>& x) {
  const double half = 0.5 * raster.cell_size();
  const Vec<2>& first = raster.first_centre();
  return x[0] >= first[0] - half && x[1] >= first[1] - half &&
         x[0] <= first[0] + (raster.columns() - 0.5) * raster.cell_size() &&
         x[1] <= first[1] + (raster.rows() - 0.5) * raster.cell_size();
}

std::string format_point(const Vec<2>& x) {
  return fmt::format("[{:.6g}, {:.6g}]", x[0], x[1]);
}

class CaseReader {
 public:
  explicit CaseReader(const cosim::config::Document& document)
      : document_(document), root_(document.root()) {}

  DepthAveragedCase read() {
    cosim::config::expect_kind(root_, "depth_averaged_case");
    const auto schema = depth_averaged_case_schema();
    schema.validate(root_);
    schema.add_defaults(root_);
    c_.file = document_.path();
    c_.config_hash = cosim::hash_bytes(document_.text());
    c_.name = root_.get<std::string>("name", c_.file.stem().string());
    read_grid();
    read_terrain();
    read_numerics();
    read_materials();
    c_.end_time = root_["time"]["end_time"].as<double>();
    read_output();
    c_.threads = root_.get<int>("threads");
    estimate_size();
    read_masses();
    read_gauges();
    return std::move(c_);
  }

 private:
  void read_grid() {
    const Node grid = root_["grid"];
    auto& g = c_.settings.grid;
    g.origin = point_of(grid["origin"]);
    const auto cells = grid["cells"].as<std::vector<double>>();
    for (int d = 0; d < 2; ++d) {
      const double n = cells[static_cast<std::size_t>(d)];
      if (!(n >= 2 && n == std::floor(n) && n <= 1e8))
        grid["cells"].fail(fmt::format("cells must be whole numbers from 2 to 1e8, not {:g}", n));
      g.cells[static_cast<std::size_t>(d)] = static_cast<int>(n);
    }
    if (grid.has("upper") == grid.has("spacing"))
      grid.fail("give exactly one of `upper` and `spacing`");
    if (auto spacing = grid.find("spacing")) {
      g.spacing = point_of(*spacing);
      if (!(g.spacing.minCoeff() > 0)) spacing->fail("the spacing must be positive");
    } else {
      const Vec<2> upper = point_of(grid["upper"]);
      for (int d = 0; d < 2; ++d) {
        if (!(upper[d] > g.origin[d])) grid["upper"].fail("upper must lie above origin");
        g.spacing[d] = (upper[d] - g.origin[d]) / g.cells[static_cast<std::size_t>(d)];
      }
    }
  }

  void read_terrain() {
    const Node terrain = root_["terrain"];
    std::optional<RasterGrid> bed;
    if (auto b = terrain.find("bed")) {
      const Node raster = (*b)["raster"];
      bed = RasterGrid::read_esri_ascii(raster.as_path());
      const Vec<2> lower = c_.settings.grid.origin, upper = c_.settings.grid.upper();
      for (const Vec<2>& corner :
           {lower, upper, Vec<2>{lower[0], upper[1]}, Vec<2>{upper[0], lower[1]}})
        if (!covers(*bed, corner))
          raster.fail(fmt::format(
              "the bed raster does not cover the ground grid: its corner {} lies outside",
              format_point(corner)));
    }
    c_.inclination_where = terrain["inclination"].key_location();
    if (c_.inclination_where.line == 0) c_.inclination_where = terrain.key_location();
    if (c_.inclination_where.line == 0) c_.inclination_where = root_.location();
    c_.settings.terrain = Terrain(terrain["inclination"].as<double>() * deg,
                                  terrain["gravity"].as<double>(), std::move(bed));
    const double fluid_density = root_["fluid"]["density"].as<double>();
    c_.settings.confined_fluid_density = fluid_density;
    if (auto water = root_.find("still_water")) {
      StillWater still{fluid_density, (*water)["level"].as<double>()};
      if (auto density = water->find("density")) {
        still.density = density->as<double>();
        c_.settings.confined_fluid_density = still.density;
      }
      c_.settings.still_water = still;
    }
  }

  void read_numerics() {
    const Node numerics = root_["numerics"];
    c_.settings.courant = numerics["courant"].as<double>();
    c_.settings.flip_fraction = numerics["flip_fraction"].as<double>();
    c_.settings.split_length = numerics["split_length"].as<double>();
    c_.settings.earth_pressure =
        EarthPressure(earth_pressure_model_from(numerics["earth_pressure"].as<std::string>()));
    if (auto obstacles = root_.find("obstacles"))
      for (const Node& node : obstacles->items()) {
        GroundObstacle o{point_of(node["min"]), point_of(node["max"])};
        if (!(o.max[0] > o.min[0] && o.max[1] > o.min[1]))
          node["max"].fail("max must lie above min in both directions");
        const auto& grid = c_.settings.grid;
        if (o.max[0] < grid.origin[0] || o.max[1] < grid.origin[1] || o.min[0] > grid.upper()[0] ||
            o.min[1] > grid.upper()[1])
          node.fail(fmt::format("the obstacle from {} to {} lies outside the grid from {} to {}",
                                format_point(o.min), format_point(o.max), format_point(grid.origin),
                                format_point(grid.upper())));
        c_.settings.obstacles.push_back(o);
      }
    const Node walls = root_["walls"];
    const char* faces[] = {"x_min", "x_max", "y_min", "y_max"};
    for (std::size_t f = 0; f < 4; ++f)
      c_.settings.walls[f] =
          walls[faces[f]].as<std::string>() == "stick" ? GroundWall::stick : GroundWall::slip;
  }

  void read_materials() {
    for (const auto& [name, node] : root_["materials"].entries()) {
      DepthAveragedMaterial m;
      m.name = name;
      m.density = node["density"].as<double>();
      m.internal_friction_angle = node["internal_friction_angle"].as<double>() * deg;
      m.basal_friction_angle = node["basal_friction_angle"].as<double>() * deg;
      m.cohesion = node["cohesion"].as<double>();
      m.structured_share = node["structured_share"].as<double>();
      m.basal_pressure_factor = node["basal_pressure_factor"].as<double>();
      m.confined_fluid_fraction = node["confined_fluid_fraction"].as<double>();
      m.in_plane.youngs_modulus = node["youngs_modulus"].as<double>();
      m.in_plane.poisson_ratio = node["poisson_ratio"].as<double>();
      if (auto eps_f = node.find("fragmentation_strain")) {
        m.fragmentation_strain = eps_f->as<double>();
        if (!node.has("cohesion_degradation"))
          eps_f->fail("needs `cohesion_degradation`: the blocks break up only as bonds break");
      }
      m.degradation = CohesionDegradation::read(node);
      c_.materials.push_back(std::move(m));
      material_names_.push_back(name);
    }
  }

  void read_output() {
    const Node output = root_["output"];
    c_.output_every = output["every"].as<double>();
    c_.gauge_every = output["gauge_every"].as<double>();
    cosim::check_output_interval(output["every"], c_.end_time);
    cosim::check_output_interval(output["gauge_every"], c_.end_time);
  }

  // Points of a mass from the area it covers, nodes from the grid: refused
  // before anything is seeded when they exceed limits.memory_gib.
  void estimate_size() {
    const auto& g = c_.settings.grid;
    double points = 0;
    for (const Node& mass : root_["masses"].items()) {
      const int n = mass["points_per_cell"].as<int>();
      const Node region = mass["region"];
      double area = 0;
      if (auto box = region.find("box")) {
        const Vec<2> size = point_of((*box)["max"]) - point_of((*box)["min"]);
        area = std::abs(size[0] * size[1]);
      } else if (auto polygon = region.find("polygon")) {
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (const Node& v : polygon->items())
          for (int d = 0; d < 2; ++d) {
            lo[d] = std::min(lo[d], point_of(v)[d]);
            hi[d] = std::max(hi[d], point_of(v)[d]);
          }
        area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
      }
      points += area / g.cell_volume() * n * n;
    }
    c_.size.add({"points", points, bytes_per_point, most_items, root_["masses"]});
    c_.size.add({"grid nodes", (g.cells[0] + 2.0) * (g.cells[1] + 2.0), bytes_per_node, most_items,
                 root_["grid"]["cells"]});
    c_.size.fixed_bytes = program_bytes;
    c_.size.not_included = "points made by splitting stretched ones";
    cosim::check_run_size(c_.size, root_);
  }

  void read_masses() {
    for (const Node& mass : root_["masses"].items()) {
      const std::string name = mass["name"].as<std::string>();
      if (std::find(c_.mass_names.begin(), c_.mass_names.end(), name) != c_.mass_names.end())
        mass["name"].fail(fmt::format("a second mass named '{}'", name));
      const Node material = mass["material"];
      const auto it =
          std::find(material_names_.begin(), material_names_.end(), material.as<std::string>());
      if (it == material_names_.end())
        material.fail(
            fmt::format("unknown material '{}'; {}", material.as<std::string>(),
                        cosim::config::suggestion(material.as<std::string>(), material_names_)));
      const int index = static_cast<int>(it - material_names_.begin());
      seed_mass(mass, index);
      c_.mass_names.push_back(name);
    }
  }

  void seed_mass(const Node& mass, int material) {
    const auto& grid = c_.settings.grid;
    const Node region = mass["region"];
    if (region.has("box") == region.has("polygon"))
      region.fail("give exactly one of `box` and `polygon`");
    Vec<2> lower, upper;
    std::optional<Polygon> polygon;
    if (auto box = region.find("box")) {
      lower = point_of((*box)["min"]);
      upper = point_of((*box)["max"]);
      if (!(upper[0] > lower[0] && upper[1] > lower[1]))
        box->fail("max must lie above min in both directions");
    } else {
      std::vector<Vec<2>> vertices;
      for (const Node& v : region["polygon"].items()) vertices.push_back(point_of(v));
      lower = upper = vertices.front();
      for (const auto& v : vertices) {
        lower = lower.cwiseMin(v);
        upper = upper.cwiseMax(v);
      }
      polygon.emplace(std::move(vertices));
    }
    for (const Vec<2>& corner : {lower, upper})
      if (corner[0] < grid.origin[0] || corner[1] < grid.origin[1] || corner[0] > grid.upper()[0] ||
          corner[1] > grid.upper()[1])
        region.fail(fmt::format("the mass reaches {}, outside the grid from {} to {}",
                                format_point(corner), format_point(grid.origin),
                                format_point(grid.upper())));
    // Seeding cells on the grid's lines, so the Gauss points integrate the
    // shape functions exactly.
    Vec<2> seed_lower, seed_upper;
    for (int d = 0; d < 2; ++d) {
      seed_lower[d] = grid.origin[d] +
                      std::floor((lower[d] - grid.origin[d]) / grid.spacing[d]) * grid.spacing[d];
      seed_upper[d] =
          grid.origin[d] +
          std::ceil((upper[d] - grid.origin[d]) / grid.spacing[d] - 1e-9) * grid.spacing[d];
    }
    const auto inside = [&](const Vec<2>& x) {
      if (polygon) return polygon->contains(x);
      return x[0] >= lower[0] && x[0] < upper[0] && x[1] >= lower[1] && x[1] < upper[1];
    };
    const Node depth = mass["depth"];
    std::function<double(const Vec<2>&)> depth_at;
    if (depth.is_map()) {
      const Node raster_key = depth["raster"];
      auto raster = std::make_shared<RasterGrid>(RasterGrid::read_esri_ascii(raster_key.as_path()));
      for (const Vec<2>& corner : {lower, upper})
        if (!covers(*raster, corner))
          raster_key.fail(
              fmt::format("the depth raster does not cover the mass's region: {} lies outside",
                          format_point(corner)));
      for (int row = 0; row < raster->rows(); ++row)
        for (int column = 0; column < raster->columns(); ++column)
          if (raster->at(column, row) < 0)
            raster_key.fail(
                fmt::format("negative depth {:g} m in the raster's row {} (from the "
                            "south), column {}",
                            raster->at(column, row), row, column));
      depth_at = [raster, inside](const Vec<2>& x) { return inside(x) ? raster->value(x) : 0.0; };
    } else {
      const double h = depth.as<double>();
      depth_at = [h, inside](const Vec<2>& x) { return inside(x) ? h : 0.0; };
    }
    Vec<2> velocity = Vec<2>::Zero();
    if (auto v = mass.find("initial_velocity")) velocity = point_of(*v);
    const std::size_t seeded = c_.particles.seed(
        seed_lower, seed_upper, grid.spacing, mass["points_per_cell"].as<int>(), depth_at,
        c_.materials[static_cast<std::size_t>(material)].density, material, velocity);
    if (seeded == 0)
      mass.fail(
          "seeds no point: its region holds no Gauss point of the grid's cells with a "
          "positive depth");
  }

  void read_gauges() {
    const auto& grid = c_.settings.grid;
    const auto gauges = root_.find("gauges");
    if (!gauges) return;
    for (const Node& node : gauges->items()) {
      DepthGauge gauge{node["name"].as<std::string>(), point_of(node["position"])};
      for (const auto& other : c_.gauges)
        if (other.name == gauge.name)
          node["name"].fail(fmt::format("a second gauge named '{}'", gauge.name));
      const Vec<2>& x = gauge.position;
      if (x[0] < grid.origin[0] || x[1] < grid.origin[1] || x[0] > grid.upper()[0] ||
          x[1] > grid.upper()[1])
        node["position"].fail(fmt::format("the gauge {} lies outside the grid", format_point(x)));
      c_.gauges.push_back(std::move(gauge));
    }
  }

  const cosim::config::Document& document_;
  Node root_;
  DepthAveragedCase c_;
  std::vector<std::string> material_names_;
};

}  // namespace

DepthAveragedCase load_depth_averaged_case(const std::filesystem::path& file) {
  const auto document = cosim::config::Document::load_file(file);
  return CaseReader(document).read();
}

bool is_depth_averaged_case(const std::filesystem::path& file) {
  try {
    const auto document = cosim::config::Document::load_file(file);
    const auto kind = document.root().find("kind");
    return kind && kind->is_scalar() && kind->as<std::string>() == "depth_averaged_case";
  } catch (const std::exception&) {
    return false;
  }
}

DepthAveragedCase load_depth_averaged_case_text(std::string_view text,
                                                const std::filesystem::path& name) {
  const auto document = cosim::config::Document::load_string(text, name);
  return CaseReader(document).read();
}

}  // namespace mpm
