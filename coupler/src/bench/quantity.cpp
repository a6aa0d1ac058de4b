#include "bench/quantity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "bench/pairing.hpp"
#include "cosim/config/document.hpp"
#include "cosim/error.hpp"
#include "cosim/io/csv_table.hpp"
#include "cosim/io/snapshot_reader.hpp"

namespace cosim::bench {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void missing(const std::string& what) {
  throw Error(ExitCode::bad_input, what);
}

double number_or(const YAML::Node& params, const char* key, double fallback) {
  return params[key] ? params[key].as<double>() : fallback;
}

// A number that may differ per backend (e.g. the pressure datum:
// absolute in ICE, gauge in OpenFOAM): `offset: 101325` or
// `offset: {ice: 101325, openfoam: 0}`.
double per_backend(const YAML::Node& params, const char* key, const std::string& backend,
                   double fallback) {
  const YAML::Node v = params[key];
  if (!v) return fallback;
  if (v.IsMap()) return v[backend] ? v[backend].as<double>() : fallback;
  return v.as<double>();
}

std::string text_or(const YAML::Node& params, const char* key, const std::string& fallback) {
  return params[key] ? params[key].as<std::string>() : fallback;
}

// A time series reduced as `at` says: end, max, min, series, or the row
// nearest a time.
Measurement reduce(const std::vector<double>& t, std::vector<double> v, const YAML::Node& params,
                   const std::string& backend, const std::string& what) {
  if (t.empty()) missing(what + ": no rows");
  const double offset = per_backend(params, "offset", backend, 0.0);
  const double divide_by = number_or(params, "divide_by", 1.0);
  for (double& x : v) x = (x - offset) / divide_by;
  const std::string at = text_or(params, "at", "end");
  Measurement m;
  m.abscissa = "t [s]";
  if (at == "series") {
    m.x = t;
    m.y = v;
  } else if (at == "end") {
    m.value = v.back();
  } else if (at == "max") {
    m.value = *std::max_element(v.begin(), v.end());
  } else if (at == "min") {
    m.value = *std::min_element(v.begin(), v.end());
  } else if (at == "first_above") {
    // The time the value first exceeds the threshold (a wave's arrival).
    const double threshold = number_or(params, "threshold", 0.0);
    const auto first = std::find_if(v.begin(), v.end(), [&](double x) { return x > threshold; });
    if (first == v.end())
      missing(fmt::format("{}: never above {:g} (largest {:g})", what, threshold,
                          *std::max_element(v.begin(), v.end())));
    m.value = t[static_cast<std::size_t>(first - v.begin())];
  } else {
    const double when = params["at"].as<double>();
    std::size_t best = 0;
    for (std::size_t i = 1; i < t.size(); ++i)
      if (std::abs(t[i] - when) < std::abs(t[best] - when)) best = i;
    m.value = v[best];
    m.time = t[best];
  }
  return m;
}

// The snapshot at `time` (the last without one). A snapshot further than
// `time_tolerance` (default 5 % of the time) from it is refused rather than
// silently measured at another time, e.g. when the run ended earlier.
std::size_t snapshot_at(const SnapshotReader& snapshots, const YAML::Node& p) {
  if (!p["time"]) return snapshots.count() - 1;
  const double t = p["time"].as<double>();
  const std::size_t s = snapshots.nearest(t);
  const double tolerance = number_or(p, "time_tolerance", 0.05 * t + 1e-12);
  if (std::abs(snapshots.times()[s] - t) > tolerance)
    missing(
        fmt::format("no snapshot within {:.3g} s of t = {:.6g} s (the nearest is at {:.6g} s; "
                    "the last at {:.6g} s)",
                    tolerance, t, snapshots.times()[s], snapshots.times().back()));
  return s;
}

Measurement gauge(const YAML::Node& p, const RunLayout& run) {
  const fs::path file = run.fluid(text_or(p, "participant", "")) / run.backend->gauge_file_name();
  const auto table = CsvTable::read(file);
  const std::string column =
      run.backend->gauge_column(p["name"].as<std::string>(), p["variable"].as<std::string>());
  return reduce(table.column(table.header().front()), table.column(column), p, run.backend->name,
                file.string() + " " + column);
}

Measurement time_series(const YAML::Node& p, const RunLayout& run) {
  const fs::path file = run.output / p["file"].as<std::string>();
  const auto table = CsvTable::read(file);
  const std::string column = p["column"].as<std::string>();
  return reduce(table.column(table.header().front()), table.column(column), p, run.backend->name,
                file.string() + " " + column);
}

std::array<double, 3> point_of(const YAML::Node& node) {
  std::array<double, 3> p{0.0, 0.0, 0.0};
  for (std::size_t d = 0; d < node.size() && d < 3; ++d) p[d] = node[d].as<double>();
  return p;
}

// The free surface over a grid cell of a VOF or multi-material fluid: the
// top of the domain minus the air in the cell's column, sum a dy, with a the
// air's share of the fluid (not of the cell: a porous cell's grains are
// under water). `water` holds the water's share of the fluid (OpenFOAM's
// alpha.water), or with `air` both materials' volume fractions (ICE).
double water_column_height(const SnapshotReader::Grid& g, const SnapshotReader::Field& water,
                           const SnapshotReader::Field* air, std::size_t element) {
  const auto nx = static_cast<std::size_t>(g.cells[0]);
  const auto ny = static_cast<std::size_t>(g.cells[1]);
  const std::size_t i = element % nx;
  const std::size_t k = element / (nx * ny);
  double height = g.origin[1] + g.spacing[1] * static_cast<double>(ny);
  for (std::size_t j = 0; j < ny; ++j) {
    const std::size_t e = (k * ny + j) * nx + i;
    const double w = water.at(e);
    const double a = air != nullptr ? air->at(e) : 1.0 - w;
    const double fluid = air != nullptr ? w + a : 1.0;
    if (fluid > 1e-12) height -= a / fluid * g.spacing[1];
  }
  return height;
}

// The normal derivative of a field at a wall of a grid, averaged along it:
// second order one-sided from the wall's value and the first two cells,
// (-8 f_w + 9 f_1 - f_2) / (3 h), signed along the axis.
Measurement wall_gradient(const YAML::Node& p, const RunLayout& run) {
  const SnapshotReader snapshots(run.fluid(text_or(p, "participant", "")),
                                 run.backend->snapshot_base());
  if (!snapshots.grid()) missing("wall_gradient needs a fluid on a uniform grid");
  const auto& g = *snapshots.grid();
  const std::size_t s = snapshot_at(snapshots, p);
  const StoredField stored = run.backend->stored_field(p["field"].as<std::string>());
  const auto f = snapshots.field(s, stored.dataset);
  const std::string wall = p["wall"].as<std::string>();
  const std::size_t axis = wall[0] == 'x' ? 0 : 1;
  const bool low = wall.substr(2) == "min";
  const double wall_value = p["wall_value"].as<double>();
  const int n_axis = g.cells[axis], n_along = g.cells[1 - axis];
  const auto at = [&](int along, int from_wall) {
    const int i = low ? from_wall : n_axis - 1 - from_wall;
    const int x = axis == 0 ? i : along, y = axis == 0 ? along : i;
    return f.at(static_cast<std::size_t>(y * g.cells[0] + x), stored.component);
  };
  double sum = 0.0;
  for (int k = 0; k < n_along; ++k) {
    const double inward = (-8.0 * wall_value + 9.0 * at(k, 0) - at(k, 1)) / (3.0 * g.spacing[axis]);
    sum += low ? inward : -inward;
  }
  Measurement m;
  m.time = snapshots.times()[s];
  m.value = sum / n_along / number_or(p, "divide_by", 1.0);
  return m;
}

Measurement profile(const YAML::Node& p, const RunLayout& run) {
  const SnapshotReader snapshots(run.fluid(text_or(p, "participant", "")),
                                 run.backend->snapshot_base());
  const std::size_t s = snapshot_at(snapshots, p);
  const std::string name = p["field"].as<std::string>();
  const bool surface_of_cells = name == "free_surface" && snapshots.grid().has_value();
  const StoredField stored = run.backend->stored_field(surface_of_cells ? "water_fraction" : name);
  const auto field = snapshots.field(s, stored.dataset);
  std::optional<SnapshotReader::Field> air;
  if (surface_of_cells && run.backend->fields.count("air_fraction")) {
    const std::string air_dataset = run.backend->stored_field("air_fraction").dataset;
    if (snapshots.has_field(s, air_dataset)) air = snapshots.field(s, air_dataset);
  }
  const auto from = point_of(p["from"]);
  const auto to = point_of(p["to"]);
  const int points = p["points"] ? p["points"].as<int>() : 50;
  const std::string axis = text_or(p, "axis", "x");
  const std::size_t a = axis == "x" ? 0 : (axis == "y" ? 1 : 2);
  const double offset = per_backend(p, "offset", run.backend->name, 0.0);
  const double divide_by = number_or(p, "divide_by", 1.0);
  Measurement m;
  m.time = snapshots.times()[s];
  m.abscissa = axis + " [m]";
  for (int i = 0; i < points; ++i) {
    const double w = static_cast<double>(i) / (points - 1);
    std::array<double, 3> at{};
    for (std::size_t d = 0; d < 3; ++d) at[d] = from[d] + w * (to[d] - from[d]);
    const std::size_t e = snapshots.element_at(s, at);
    const double value =
        surface_of_cells ? water_column_height(*snapshots.grid(), field, air ? &*air : nullptr, e)
                         : field.at(e, stored.component);
    m.x.push_back(at[a]);
    m.y.push_back((value - offset) / divide_by);
  }
  return m;
}

// The front along the floor: the downstream edge of the last bottom-row cell
// holding more water than the threshold, in every snapshot.
Measurement water_front(const YAML::Node& p, const RunLayout& run) {
  const SnapshotReader snapshots(run.fluid(text_or(p, "participant", "")),
                                 run.backend->snapshot_base());
  const double threshold = number_or(p, "threshold", 0.5);
  const double length_scale = number_or(p, "length_scale", 1.0);
  const double time_scale = number_or(p, "time_scale", 1.0);
  if (run.backend->front_field.empty())
    missing(
        fmt::format("the {} backend has no field a water front is measured on (front_field "
                    "in {})",
                    run.backend->name, run.backend->file.string()));
  const StoredField stored = run.backend->stored_field(run.backend->front_field);
  Measurement m;
  m.abscissa = time_scale == 1.0 ? "t [s]" : fmt::format("t x {:.5g} [1]", time_scale);
  if (p["start"]) {
    m.x.push_back(p["start"][0].as<double>());
    m.y.push_back(p["start"][1].as<double>());
  }
  for (std::size_t s = 0; s < snapshots.count(); ++s) {
    const auto values = snapshots.field(s, stored.dataset);
    const auto centres = snapshots.positions(s);
    double front = 0.0;
    if (const auto& g = snapshots.grid()) {
      for (int i = 0; i < g->cells[0]; ++i)
        if (values.at(static_cast<std::size_t>(i)) > threshold)
          front = g->origin[0] + (i + 1) * g->spacing[0];
    } else {
      // A line: cell edges halfway between centres.
      for (std::size_t e = 0; e < centres.size(); ++e) {
        if (values.at(e) <= threshold) continue;
        const double half = e + 1 < centres.size()
                                ? 0.5 * (centres[e + 1][0] - centres[e][0])
                                : (e > 0 ? 0.5 * (centres[e][0] - centres[e - 1][0]) : 0.0);
        front = std::max(front, centres[e][0] + half);
      }
    }
    const double t = snapshots.times()[s] * time_scale;
    if (!m.x.empty() && t <= m.x.back()) continue;
    m.x.push_back(t);
    m.y.push_back(front / length_scale);
  }
  return m;
}

struct Points {
  double time = 0.0;
  std::vector<std::array<double, 3>> xyz;
  std::vector<double> speed;
};

// The moving bodies of an MPM case: those not rigid, by index in `bodies`.
std::set<int> moving_bodies(const fs::path& soil_case) {
  std::set<int> moving;
  const auto doc = config::Document::load_file(soil_case);
  const YAML::Node bodies = doc.root().yaml()["bodies"];
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (!bodies[b]["rigid"]) moving.insert(static_cast<int>(b));
  return moving;
}

Points moving_points(const SnapshotReader& snapshots, std::size_t s, const std::set<int>& moving) {
  Points out;
  out.time = snapshots.times()[s];
  const auto xyz = snapshots.positions(s);
  const auto body = snapshots.field(s, "body");
  const auto velocity = snapshots.field(s, "velocity");
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    if (!moving.count(static_cast<int>(body.at(i)))) continue;
    out.xyz.push_back(xyz[i]);
    double v2 = 0.0;
    for (int c = 0; c < velocity.components; ++c) v2 += velocity.at(i, c) * velocity.at(i, c);
    out.speed.push_back(std::sqrt(v2));
  }
  if (out.xyz.empty()) missing("the soil's snapshots hold no point of a moving body");
  return out;
}

// Zheng et al.'s toe: the furthest point within `band` of the lowest one.
double toe(const Points& p, double band) {
  double bottom = std::numeric_limits<double>::infinity();
  for (const auto& x : p.xyz) bottom = std::min(bottom, x[1]);
  double front = -std::numeric_limits<double>::infinity();
  for (const auto& x : p.xyz)
    if (x[1] <= bottom + band) front = std::max(front, x[0]);
  return front;
}

double measure_points(const std::string& measure, const Points& now, const Points& start,
                      double band) {
  const auto extreme = [](const Points& p, std::size_t axis, bool largest) {
    double v = largest ? -std::numeric_limits<double>::infinity()
                       : std::numeric_limits<double>::infinity();
    for (const auto& x : p.xyz) v = largest ? std::max(v, x[axis]) : std::min(v, x[axis]);
    return v;
  };
  if (measure == "front" || measure == "front_series") return extreme(now, 0, true);
  if (measure == "back") return extreme(now, 0, false);
  if (measure == "height" || measure == "height_series") return extreme(now, 1, true);
  if (measure == "height_change") return extreme(now, 1, true) / extreme(start, 1, true);
  if (measure == "runout") return toe(now, band) - toe(start, band);
  if (measure == "toe") return toe(now, band);
  if (measure == "max_speed") return *std::max_element(now.speed.begin(), now.speed.end());
  missing("unknown soil measure '" + measure + "'");
}

Measurement soil(const YAML::Node& p, const RunLayout& run) {
  const std::string participant = text_or(p, "participant", soil_participant);
  // A run of the soil's own solver holds its particles at the top.
  const fs::path dir = run.backend->is_soil() ? run.output : run.participant(participant);
  const SnapshotReader snapshots(dir, "particles");
  const auto moving = moving_bodies(run.soil_case(participant));
  const std::string what = p["measure"].as<std::string>();
  const double band = number_or(p, "base_band", 0.1);
  const double divide_by = number_or(p, "divide_by", 1.0);
  const Points start = moving_points(snapshots, 0, moving);
  Measurement m;
  if (what.size() > 7 && what.substr(what.size() - 7) == "_series") {
    m.abscissa = "t [s]";
    for (std::size_t s = 0; s < snapshots.count(); ++s) {
      m.x.push_back(snapshots.times()[s]);
      m.y.push_back(measure_points(what, moving_points(snapshots, s, moving), start, band) /
                    divide_by);
    }
    return m;
  }
  const std::size_t s = snapshot_at(snapshots, p);
  m.time = snapshots.times()[s];
  m.value = measure_points(what, moving_points(snapshots, s, moving), start, band) / divide_by;
  return m;
}

Measurement summary(const YAML::Node& p, const RunLayout& run) {
  const fs::path file =
      (p["participant"] ? run.participant(p["participant"].as<std::string>()) : run.output) /
      "summary.json";
  std::ifstream in(file);
  if (!in) missing("cannot read " + file.string());
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    missing(fmt::format("{}: {}", file.string(), e.what()));
  }
  const std::string pointer = p["value"].as<std::string>();
  try {
    const auto& v = j.at(nlohmann::json::json_pointer(pointer));
    if (!v.is_number()) missing(fmt::format("{}: {} is not a number", file.string(), pointer));
    Measurement m;
    m.value = v.get<double>() / number_or(p, "divide_by", 1.0);
    return m;
  } catch (const nlohmann::json::exception&) {
    missing(fmt::format("{}: no number at {}", file.string(), pointer));
  }
}

}  // namespace

Measurement measure(const QuantitySpec& q, const RunLayout& run) {
  static const std::map<std::string,
                        std::function<Measurement(const YAML::Node&, const RunLayout&)>>
      kinds{{"gauge", gauge},
            {"time_series", time_series},
            {"profile", profile},
            {"water_front", water_front},
            {"soil", soil},
            {"summary", summary},
            {"wall_gradient", wall_gradient}};
  const auto it = kinds.find(q.kind);
  if (it == kinds.end()) missing("unknown quantity kind '" + q.kind + "'");
  return it->second(q.params, run);
}

}  // namespace cosim::bench
