#include "case/body_seeding.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cosim/error.hpp"
#include "mpm/geometry/box.hpp"
#include "mpm/geometry/particle_file.hpp"
#include "mpm/geometry/polygon.hpp"
#include "mpm/geometry/polyhedron.hpp"
#include "mpm/geometry/seeding.hpp"

namespace mpm::case_loading {

namespace {

using cosim::config::Node;

template <int Dim>
Vec<Dim> point(const Node& node) {
  const auto values = node.as<std::vector<double>>();
  if (values.size() != static_cast<std::size_t>(Dim))
    node.fail(
        fmt::format("expected {} coordinates (dimension: {}), got {}", Dim, Dim, values.size()));
  Vec<Dim> x;
  for (int d = 0; d < Dim; ++d) x[d] = values[static_cast<std::size_t>(d)];
  return x;
}

// An InputError of the geometry module, re-thrown with the YAML key: at
// `node` when it carries no location of its own (a region's own check),
// else at its location (a line of a points file) naming the key.
template <class F>
auto located_at(const Node& node, F&& f) {
  try {
    return f();
  } catch (const cosim::InputError& e) {
    if (e.where().file.empty()) node.fail(e.what());
    std::string what = e.what();
    const std::string prefix =
        fmt::format("{}:{}:{}: ", e.where().file, e.where().line, e.where().column);
    if (what.rfind(prefix, 0) == 0) what.erase(0, prefix.size());
    throw cosim::InputError(e.where(), node.key_path(), what);
  }
}

// Cell-aligned seeding with counts per direction: n points per direction
// everywhere is the module's regular pattern; unequal counts are the
// regular pattern with one point per cell of the grid refined n_d times in
// direction d (the same sub-cell centres, volumes and half-lengths).
template <int Dim>
std::pair<GridGeometry<Dim>, SeedingPattern> seeding_grid(const GridSpec& spec,
                                                          const std::array<int, 3>& counts,
                                                          Seeding seeding) {
  GridGeometry<Dim> grid;
  SeedingPattern pattern;
  bool equal = true;
  int product = 1;
  for (int d = 0; d < Dim; ++d) {
    const auto i = static_cast<std::size_t>(d);
    grid.origin[d] = spec.origin[d];
    grid.spacing[d] = spec.spacing[d];
    grid.cells[i] = spec.cells[i];
    equal = equal && counts[i] == counts[0];
    product *= counts[i];
  }
  if (seeding == Seeding::r2) {
    pattern.kind = SeedingPattern::Kind::quasi_random;
    pattern.per_cell = product;
  } else if (equal) {
    pattern.per_direction = counts[0];
  } else {
    pattern.per_direction = 1;
    for (int d = 0; d < Dim; ++d) {
      const auto i = static_cast<std::size_t>(d);
      grid.spacing[d] /= counts[i];
      grid.cells[i] *= counts[i];
    }
  }
  return {grid, pattern};
}

// The grid grown by whole cells to cover `bounds`: the geometry module
// seeds grid cells only, and particles outside the grid must be seen (and
// refused by the loader), not silently dropped.
template <int Dim>
GridGeometry<Dim> covering(GridGeometry<Dim> grid, const Box<Dim>& bounds) {
  for (int d = 0; d < Dim; ++d) {
    const auto i = static_cast<std::size_t>(d);
    const double upper = grid.origin[d] + grid.spacing[d] * grid.cells[i];
    const int below = std::max(
        0, static_cast<int>(std::ceil((grid.origin[d] - bounds.lower[d]) / grid.spacing[d])));
    const int above =
        std::max(0, static_cast<int>(std::ceil((bounds.upper[d] - upper) / grid.spacing[d])));
    grid.origin[d] -= below * grid.spacing[d];
    grid.cells[i] += below + above;
  }
  return grid;
}

// The particles a region of `volume` gets: its share of the grid's cells
// times the points per cell (the points near its boundary fall in or out).
template <int Dim>
double particles_in(double volume, const GridSpec& spec, const std::array<int, 3>& counts) {
  double per_cell = 1.0, cell = 1.0;
  for (int d = 0; d < Dim; ++d) {
    per_cell *= counts[static_cast<std::size_t>(d)];
    cell *= spec.spacing[d];
  }
  return volume / cell * per_cell;
}

template <int Dim>
SeededParticles<Dim> seed(const Node& geometry, const GridSpec& spec,
                          const std::array<int, 3>& counts, Seeding seeding,
                          const BeforeSeeding& before_seeding) {
  // A region is estimated before the seeding grid is even refined, then
  // seeded on the grid grown to cover it.
  const auto seed_inside = [&](const auto& region, double volume) {
    before_seeding(particles_in<Dim>(volume, spec, counts));
    const auto [grid, pattern] = seeding_grid<Dim>(spec, counts, seeding);
    return seed_region<Dim>(region, covering<Dim>(grid, region.bounding_box()), pattern);
  };
  if (auto box = geometry.find("box")) {
    Box<Dim> region{point<Dim>((*box)["min"]), point<Dim>((*box)["max"])};
    if (!(region.lower.array() < region.upper.array()).all())
      (*box)["max"].fail("box max must exceed min in every direction");
    return seed_inside(region, (region.upper - region.lower).prod());
  }
  if (auto polygon = geometry.find("polygon")) {
    if constexpr (Dim == 2) {
      std::vector<Vec<2>> vertices;
      for (const Node& v : polygon->items()) vertices.push_back(point<2>(v));
      const Polygon region = located_at(*polygon, [&] { return Polygon(std::move(vertices)); });
      return seed_inside(region, region.area());
    } else {
      polygon->fail_at_key("a polygon needs dimension: 2 (use a polyhedron in 3D)");
    }
  }
  if (auto polyhedron = geometry.find("polyhedron")) {
    if constexpr (Dim == 3) {
      std::vector<Vec<3>> vertices;
      for (const Node& v : (*polyhedron)["vertices"].items()) vertices.push_back(point<3>(v));
      std::vector<std::array<int, 3>> triangles;
      for (const Node& t : (*polyhedron)["triangles"].items()) {
        const auto values = t.as<std::vector<int>>();
        triangles.push_back({values[0], values[1], values[2]});
      }
      const Polyhedron region = located_at(
          *polyhedron, [&] { return Polyhedron(std::move(vertices), std::move(triangles)); });
      return seed_inside(region, region.volume());
    } else {
      polyhedron->fail_at_key("a polyhedron needs dimension: 3 (use a polygon in 2D)");
    }
  }
  // Listed particles: as many as the file holds, counted once read.
  const Node points = geometry["points"];
  SeededParticles<Dim> listed = located_at(
      points, [&] { return read_particle_file<Dim>(points.as_path().string()).particles; });
  before_seeding(static_cast<double>(listed.positions.size()));
  return listed;
}

template <int Dim>
Vec3d widened(const Vec<Dim>& v) {
  Vec3d x = Vec3d::Zero();
  x.template head<Dim>() = v;
  return x;
}

template <int Dim>
SeededBody seed_body(const Node& geometry, const GridSpec& grid,
                     const std::array<int, 3>& particles_per_cell, Seeding seeding,
                     const BeforeSeeding& before_seeding) {
  const SeededParticles<Dim> particles =
      seed<Dim>(geometry, grid, particles_per_cell, seeding, before_seeding);
  SeededBody body;
  body.volumes = particles.volumes;
  for (const auto& x : particles.positions) body.positions.push_back(widened<Dim>(x));
  for (const auto& h : particles.half_lengths) body.half_lengths.push_back(widened<Dim>(h));
  return body;
}

}  // namespace

SeededBody seed_body(const Node& geometry, int dimension, const GridSpec& grid,
                     const std::array<int, 3>& particles_per_cell, Seeding seeding,
                     const BeforeSeeding& before_seeding) {
  if (dimension == 2)
    return seed_body<2>(geometry, grid, particles_per_cell, seeding, before_seeding);
  return seed_body<3>(geometry, grid, particles_per_cell, seeding, before_seeding);
}

}  // namespace mpm::case_loading
