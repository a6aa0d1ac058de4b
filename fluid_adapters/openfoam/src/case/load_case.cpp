#include "openfoam/case/load_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/config/document.hpp"
#include "cosim/config/kind.hpp"
#include "cosim/error.hpp"
#include "cosim/io/content_hash.hpp"
#include "cosim/io/output_schedule.hpp"
#include "openfoam/case/case_schema.hpp"
#include "openfoam/case/case_size.hpp"
#include "openfoam/foam/control_dict.hpp"

namespace openfoam {

using cosim::config::Node;

namespace {

constexpr const char* side_names[] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
constexpr const char* axis_names[] = {"x", "y", "z"};

SideKind side_kind(const std::string& name) {
  if (name == "slip") return SideKind::slip;
  if (name == "atmosphere") return SideKind::atmosphere;
  return SideKind::wall;
}

class CaseReader {
 public:
  CaseReader(const cosim::config::Document& document, int job_processes)
      : document_(document), root_(document.root()), job_processes_(job_processes) {}

  CaseDescription read() {
    cosim::config::expect_kind(root_, "openfoam_case");
    openfoam_case_schema().validate(root_);
    openfoam_case_schema().add_defaults(root_);
    CaseDescription c;
    c.file = document_.path();
    c.config_hash = cosim::hash_bytes(document_.text());
    c.name = root_["name"].as<std::string>();
    c.solver = root_.get<std::string>("solver");
    const auto generate = root_.find("generate");
    const auto directory = root_.find("directory");
    if (generate && directory) directory->fail("give either `generate` or `directory`, not both");
    if (!generate && !directory) {
      root_.fail("give `generate` (a case made from the YAML) or `directory` (an OpenFOAM case)");
    }
    if (generate) c.generate = read_generated(*generate);
    if (directory) c.directory = directory->as_path();
    c.end_time = root_["end_time"].as<double>();
    c.time_step = root_["time_step"].as<double>();
    if (c.time_step > c.end_time) {
      root_["time_step"].fail(
          fmt::format("time step {} s is longer than the end time {} s", c.time_step, c.end_time));
    }
    {
      const Node output = root_["output"];
      c.output_every = output.get<double>("every");
      cosim::check_output_interval(output["every"], c.end_time);
      if (auto gauges = output.find("gauges")) {
        for (const Node& g : gauges->items()) {
          Gauge gauge{g["name"].as<std::string>(), {}};
          const auto point = g["point"].as<std::vector<double>>();
          std::copy(point.begin(), point.end(), gauge.point.begin());
          c.gauges.push_back(gauge);
        }
      }
      if (auto waves = output.find("wave_gauges")) {
        if (!c.generate) waves->fail("wave gauges need a generated case (its columns of cells)");
        for (const Node& g : waves->items()) {
          WaveGauge gauge{g["name"].as<std::string>(), g["x"].as<double>(), g.get<double>("z")};
          const GeneratedCase& box = *c.generate;
          if (gauge.x < box.origin[0] || gauge.x > box.upper[0]) {
            g["x"].fail(fmt::format("x = {} m is outside the grid [{}, {}] m", gauge.x,
                                    box.origin[0], box.upper[0]));
          }
          c.wave_gauges.push_back(gauge);
        }
      }
    }
    if (c.output_every > 0.0 && !is_whole_number_of_steps(c.output_every, c.time_step)) {
      root_["output"]["every"].fail(
          fmt::format("the snapshot interval {} s is not a whole number of time steps of {} s",
                      c.output_every, c.time_step));
    }
    c.window = root_.get<double>("window", c.output_every > 0.0 ? c.output_every : c.end_time);
    if (auto window = root_.find("window");
        window && !is_whole_number_of_steps(c.window, c.time_step)) {
      window->fail(fmt::format("the window {} s is not a whole number of time steps of {} s",
                               c.window, c.time_step));
    }
    // Every window starts OpenFOAM afresh (about a second each).
    if (auto window = root_.find("window");
        window && c.end_time / c.window > cosim::max_output_count) {
      window->fail(
          fmt::format("the window {} s starts OpenFOAM {:.3g} times over the run's {} s, "
                      "more than {:g}; give a longer window",
                      c.window, c.end_time / c.window, c.end_time, cosim::max_output_count));
    }
    if (!is_whole_number_of_steps(c.end_time, c.time_step)) {
      root_["end_time"].fail(
          fmt::format("the end time {} s is not a whole number of time steps of {} s", c.end_time,
                      c.time_step));
    }
    c.keep_time_directories = root_.get<bool>("keep_time_directories");
    c.window_timeout = root_.get<double>("window_timeout");
    if (auto parallel = root_.find("parallel")) {
      c.processes = (*parallel)["processes"].as<int>();
      c.split = {c.processes, 1, 1};
      if (job_processes_ > 0 && c.processes != job_processes_)
        (*parallel)["processes"].fail(fmt::format(
            "the job runs this participant's OpenFOAM on {} processes (its `ranks`), the case on "
            "{}; give one count, or leave `parallel` out of the case",
            job_processes_, c.processes));
      if (auto split = parallel->find("split")) {
        c.split_given = true;
        const auto blocks = split->as<std::vector<double>>();
        long product = 1;
        for (std::size_t d = 0; d < 3; ++d) {
          const double b = d < blocks.size() ? blocks[d] : 1.0;
          if (!(b >= 1.0) || b != std::floor(b)) {
            split->fail(fmt::format("blocks per direction must be whole numbers >= 1, got {}", b));
          }
          c.split[d] = static_cast<int>(b);
          product *= c.split[d];
        }
        if (product != c.processes) {
          split->fail(fmt::format("the blocks {} x {} x {} make {} processes, not {}", c.split[0],
                                  c.split[1], c.split[2], product, c.processes));
        }
      }
    }
    if (auto soil = root_.find("soil")) {
      if (soil->get<std::string>("model") == "porosity_zones") {
        c.soil.model = SoilModel::porosity_zones;
        if (c.has_cloud()) {
          (*soil)["model"].fail("porosity_zones run interFoam (`solver: interFoam`), not " +
                                c.solver);
        }
      } else if (!c.has_cloud()) {
        soil->fail("`soil` with parcels needs `solver: MPPICInterFoam` (the soil's parcels)");
      }
      c.soil.zones = soil->get<int>("zones");
      c.soil.parcel_density = soil->get<double>("parcel_density");
      c.soil.max_solid_fraction = soil->get<double>("max_solid_fraction");
      c.soil.minimum_solid_fraction = soil->get<double>("minimum_solid_fraction");
      c.soil.displaced_water = soil->get<bool>("displaced_water");
    }
    if (job_processes_ > 0 && !root_.find("parallel")) {
      c.processes = job_processes_;
      c.split = {c.processes, 1, 1};
    }
    c.size = run_size(c, root_);
    cosim::check_run_size(c.size, root_);
    return c;
  }

 private:
  Vector3 vector_of(const Node& node, int dimension) const {
    const auto v = node.as<std::vector<double>>();
    if (static_cast<int>(v.size()) != dimension) {
      node.fail(
          fmt::format("expected {} values for a {}D case, got {}", dimension, dimension, v.size()));
    }
    Vector3 x{};
    std::copy(v.begin(), v.end(), x.begin());
    return x;
  }

  GeneratedCase read_generated(const Node& g) const {
    GeneratedCase c;
    c.dimension = g["dimension"].as<int>();
    const int dim = c.dimension;
    const Node grid = g["grid"];
    c.origin = vector_of(grid["origin"], dim);
    c.upper = vector_of(grid["upper"], dim);
    const Node cells = grid["cells"];
    const auto counts = cells.as<std::vector<double>>();
    if (static_cast<int>(counts.size()) != dim) {
      cells.fail(
          fmt::format("expected {} cell counts for a {}D case, got {}", dim, dim, counts.size()));
    }
    for (int d = 0; d < dim; ++d) {
      const auto k = static_cast<std::size_t>(d);
      if (!(counts[k] >= 1.0) || counts[k] != std::floor(counts[k]) || counts[k] > 1e6) {
        cells.fail(fmt::format("cells along {} must be a whole number >= 1, got {}", axis_names[d],
                               counts[k]));
      }
      c.cells[k] = static_cast<int>(counts[k]);
      if (!(c.upper[k] > c.origin[k])) {
        grid["upper"].fail(fmt::format("upper corner {} is not above the origin {} along {}",
                                       c.upper[k], c.origin[k], axis_names[d]));
      }
    }
    if (dim == 2) {
      // One cell thick along z, as thick as the smallest spacing.
      const double thickness = std::min((c.upper[0] - c.origin[0]) / c.cells[0],
                                        (c.upper[1] - c.origin[1]) / c.cells[1]);
      c.origin[2] = 0.0;
      c.upper[2] = thickness;
      c.cells[2] = 1;
    }
    if (auto gravity = g.find("gravity")) c.gravity = vector_of(*gravity, dim);
    const Node fluids = g["fluids"];
    c.water = {fluids["water"]["density"].as<double>(), fluids["water"]["viscosity"].as<double>()};
    c.air = {fluids["air"]["density"].as<double>(), fluids["air"]["viscosity"].as<double>()};
    c.surface_tension = g.get<double>("surface_tension");
    c.initial_pressure = g.get<double>("initial_pressure");
    if (auto regions = g.find("water")) {
      for (const Node& region : regions->items()) {
        const Node box = region["box"];
        WaterBox w{vector_of(box["lower"], dim), vector_of(box["upper"], dim)};
        if (dim == 2) {
          w.lower[2] = c.origin[2];
          w.upper[2] = c.upper[2];
        }
        for (int d = 0; d < dim; ++d) {
          const auto k = static_cast<std::size_t>(d);
          if (!(w.upper[k] > w.lower[k])) {
            box["upper"].fail(fmt::format("upper corner {} is not above the lower {} along {}",
                                          w.upper[k], w.lower[k], axis_names[d]));
          }
        }
        c.water_regions.push_back(w);
      }
    }
    if (auto boundaries = g.find("boundaries")) {
      for (int s = 0; s < 2 * dim; ++s) {
        if (auto side = boundaries->find(side_names[s])) {
          const auto k = static_cast<std::size_t>(s);
          if (side->is_map()) {
            c.sides[k] = SideKind::pressure;
            c.side_pressure[k] = (*side)["pressure"].as<double>();
          } else {
            c.sides[k] = side_kind(side->as<std::string>());
          }
        }
      }
      if (dim == 2) {
        for (const char* s : {"z_min", "z_max"}) {
          if (auto side = boundaries->find(s)) {
            side->fail("a 2D case's z sides are OpenFOAM's empty front and back");
          }
        }
      }
    }
    return c;
  }

  const cosim::config::Document& document_;
  Node root_;
  int job_processes_ = 0;  // the job's `ranks` of this participant; 0: the case's own
};

}  // namespace

const char* to_string(SideKind kind) {
  switch (kind) {
    case SideKind::wall:
      return "wall";
    case SideKind::slip:
      return "slip";
    case SideKind::atmosphere:
      return "atmosphere";
    case SideKind::pressure:
      return "pressure";
  }
  return "?";
}

std::size_t GeneratedCase::cell_count() const {
  return static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) *
         static_cast<std::size_t>(cells[2]);
}

Vector3 GeneratedCase::spacing() const {
  Vector3 h{};
  for (std::size_t d = 0; d < 3; ++d) h[d] = (upper[d] - origin[d]) / cells[d];
  return h;
}

CaseDescription load_case(const std::filesystem::path& file, int job_processes) {
  const auto document = cosim::config::Document::load_file(file);
  return CaseReader(document, job_processes).read();
}

CaseDescription load_case_text(std::string_view text, const std::filesystem::path& name,
                               int job_processes) {
  const auto document = cosim::config::Document::load_string(text, name);
  return CaseReader(document, job_processes).read();
}

}  // namespace openfoam
