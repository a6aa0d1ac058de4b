#include "mpm/depth_averaged/depth_averaged_coupling.hpp"

#include <stdexcept>

#include "cosim/fields.hpp"

namespace mpm {

namespace {

namespace f = cosim::fields;
constexpr const char* ground_mesh = "ground";

}  // namespace

DepthAveragedCoupling::DepthAveragedCoupling(cosim::Participant& participant,
                                             const DepthAveragedSolver& solver,
                                             double fluid_density)
    : participant_(participant),
      deposit_(ground_cells(solver.settings().grid)),
      fluid_density_(fluid_density) {
  if (solver.settings().terrain.inclination() != 0.0)
    throw std::invalid_argument(
        "a coupled depth-averaged mass needs an inclination of 0: the water's grid is "
        "horizontal (give the slope in the bed raster)");
}

void DepthAveragedCoupling::declare(const DepthAveragedSolver& solver) {
  participant_.declare_mesh({ground_mesh, deposit_.cells()});
  for (const f::Field* field : {&f::column_volume, &f::column_mass, &f::column_momentum,
                                &f::structured_mass, &f::released_fluid_volume, &f::bed_elevation})
    participant_.declare_write(field->on(ground_mesh, 2));
  for (const f::Field* field : {&f::momentum_exchange_impulse, &f::free_surface_elevation}) {
    cosim::FieldSpec read = field->on(ground_mesh, 2);
    read.optional = true;
    participant_.declare_read(read, 0.0);
  }
  const auto& cells = deposit_.cells();
  std::vector<double> bed(cells.size());
  for (std::size_t c = 0; c < bed.size(); ++c) {
    const cosim::Vec3 x = cells.position(c);
    bed[c] = solver.settings().terrain.bed_elevation({x[0], x[1]});
  }
  participant_.write(f::bed_elevation.name, bed);
  participant_.write(f::released_fluid_volume.name, std::vector<double>(cells.size(), 0.0));
  write_columns(solver);
}

void DepthAveragedCoupling::write_columns(const DepthAveragedSolver& solver) {
  const auto& points = solver.particles();
  const std::size_t n = points.size();
  std::vector<double> structured(n), momentum(2 * n);
  for (std::size_t p = 0; p < n; ++p) {
    structured[p] = points.structured_share[p] * points.mass[p];
    momentum[2 * p] = points.mass[p] * points.velocity[p][0];
    momentum[2 * p + 1] = points.mass[p] * points.velocity[p][1];
  }
  participant_.write(f::column_volume.name, deposit_.deposit(points.position, points.volume, 1));
  participant_.write(f::column_mass.name, deposit_.deposit(points.position, points.mass, 1));
  participant_.write(f::column_momentum.name, deposit_.deposit(points.position, momentum, 2));
  participant_.write(f::structured_mass.name, deposit_.deposit(points.position, structured, 1));
}

void DepthAveragedCoupling::start_window(DepthAveragedSolver& solver) {
  const auto& cells = deposit_.cells();
  const auto& points = solver.particles();
  if (participant_.is_sent(f::momentum_exchange_impulse.name)) {
    std::vector<double> impulse(2 * cells.size());
    participant_.read(f::momentum_exchange_impulse.name, impulse);
    std::vector<double> unplaced;
    const std::vector<double> per_point =
        deposit_.distribute(points.position, points.mass, impulse, 2, &unplaced);
    std::vector<Vec<2>> kicks(points.size());
    for (std::size_t p = 0; p < kicks.size(); ++p)
      kicks[p] = {per_point[2 * p], per_point[2 * p + 1]};
    for (std::size_t c = 0; c < cells.size(); ++c)
      impulse_received_ += Vec<2>{impulse[2 * c], impulse[2 * c + 1]};
    impulse_unplaced_ += Vec<2>{unplaced[0], unplaced[1]};
    solver.apply_impulse(kicks);
  }
  if (participant_.is_sent(f::free_surface_elevation.name)) {
    std::vector<double> surface(cells.size());
    participant_.read(f::free_surface_elevation.name, surface);
    const auto nodes = solver.nodes_per_direction();
    std::vector<double> at_nodes(static_cast<std::size_t>(nodes[0]) *
                                 static_cast<std::size_t>(nodes[1]));
    for (std::size_t i = 0; i < at_nodes.size(); ++i) {
      double eta = 0.0;
      deposit_.for_each_share(solver.node_position(i),
                              [&](std::size_t c, double share) { eta += share * surface[c]; });
      at_nodes[i] = eta;
    }
    solver.set_fluid_surface(fluid_density_, std::move(at_nodes));
  }
}

void DepthAveragedCoupling::after_step(DepthAveragedSolver& solver, double dt, bool window_ends) {
  std::vector<double> released = solver.take_released_fluid();
  for (double v : released) released_this_window_ += v;
  for (double& v : released) v /= dt;
  participant_.write(f::released_fluid_volume.name,
                     deposit_.deposit(solver.particles().position, released, 1));
  if (window_ends) {
    write_columns(solver);
    fluid_released_ += released_this_window_;
    released_last_window_ = released_this_window_;
    released_this_window_ = 0.0;
  }
}

}  // namespace mpm
