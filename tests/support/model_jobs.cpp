#include "model_jobs.hpp"

#include <fmt/format.h>

#include "text_files.hpp"

namespace cosim::testing {

namespace fs = std::filesystem;

namespace {

std::string participant_config(const char* writes, const char* reads, double constant,
                               double coefficient) {
  return fmt::format(R"(kind: test_participant
dt: 4.0e-3
mesh: {{dim: 1, origin: [0.0], spacing: [0.25], cells: [4]}}
writes:
  - {{name: {0}, function: [{2}, 0, 0, 0, 0], response: {{read: {1}, coefficient: {3}}}}}
reads:
  - {{name: {1}}}
)",
                     writes, reads, constant, coefficient);
}

}  // namespace

void write_fixed_point_case(const fs::path& dir, const std::string& coupling, double a_gain,
                            double b_gain, const std::string& b_args) {
  write_text(dir / "job.yaml", fmt::format(R"(kind: job
name: fixed_point
end_time: 0.1
window: 1.0e-2
participants:
  left:
    executable: cosim_test_participant
    config: left.yaml
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{a: grid}}
    reads: {{b: grid}}
  right:
    executable: cosim_test_participant
    config: right.yaml
    args: {1}
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{b: grid}}
    reads: {{a: grid}}
exchange:
  - {{field: a, from: left, to: right, mapping: consistent}}
  - {{field: b, from: right, to: left, mapping: consistent}}
{0})",
                                           coupling, b_args));
  write_text(dir / "left.yaml", participant_config("a", "b", 1.0, a_gain));
  write_text(dir / "right.yaml", participant_config("b", "a", 2.0, b_gain));
}

void write_stiff_drag_case(const fs::path& dir, const std::string& coupling) {
  write_text(dir / "job.yaml", fmt::format(R"(kind: job
name: stiff_drag
end_time: 0.1
window: {}
participants:
  water:
    executable: cosim_test_participant
    config: water.yaml
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{fluid_velocity: grid, fluid_bulk_density: grid}}
    reads: {{momentum_exchange_impulse: grid}}
  soil:
    executable: cosim_test_participant
    config: soil.yaml
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{solid_fraction: grid, solid_velocity: grid, solid_bulk_density: grid}}
    reads: {{momentum_exchange_impulse: grid}}
momentum_exchange:
  fluid: water
  solid: soil
  mesh: water.grid
  drag: {{law: constant, coefficient: {:.17g}}}
{})",
                                           model_window, model_drag, coupling));
  const std::string grid = "mesh: {dim: 1, origin: [0.0], spacing: [0.25], cells: [4]}\n";
  const std::string impulse =
      "  - {name: momentum_exchange_impulse, unit: kg m/s, quantity: extensive, time: "
      "integral}\n";
  write_text(dir / "water.yaml",
             "kind: test_participant\ndt: 1.0e-3\n" + grid +
                 "writes:\n  - {name: fluid_velocity, unit: m/s}\n"
                 "  - {name: fluid_bulk_density, unit: kg/m^3, function: [600.0, 0, 0, 0, 0]}\n"
                 "reads:\n" +
                 impulse +
                 "dynamics: {velocity: fluid_velocity, impulse: momentum_exchange_impulse, "
                 "bulk_density: 600.0, body_force: [6000.0]}\n");
  write_text(dir / "soil.yaml",
             "kind: test_participant\ndt: 7.0e-4\n" + grid +
                 "writes:\n  - {name: solid_fraction, function: [0.4, 0, 0, 0, 0]}\n"
                 "  - {name: solid_velocity, unit: m/s}\n"
                 "  - {name: solid_bulk_density, unit: kg/m^3, function: [1590.0, 0, 0, 0, 0]}\n"
                 "reads:\n" +
                 impulse +
                 "dynamics: {velocity: solid_velocity, impulse: momentum_exchange_impulse, "
                 "bulk_density: 1590.0, body_force: [0.0]}\n");
}

void write_stiff_heat_case(const fs::path& dir, const std::string& coupling) {
  const double coefficient = 1.0 / (heat_tau * (1.0 / heat_c_f + 1.0 / heat_c_s));
  write_text(dir / "job.yaml", fmt::format(R"(kind: job
name: stiff_heat
end_time: 0.1
window: {}
participants:
  water:
    executable: cosim_test_participant
    config: water.yaml
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{fluid_temperature: grid, fluid_heat_capacity: grid}}
    reads: {{heat_exchange_energy: grid}}
  rock:
    executable: cosim_test_participant
    config: rock.yaml
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{solid_temperature: grid, solid_heat_capacity: grid}}
    reads: {{heat_exchange_energy: grid}}
energy_exchange:
  fluid: water
  solid: rock
  mesh: water.grid
  coefficient: {:.17g}
{})",
                                           heat_window, coefficient, coupling));
  const auto side = [&](const char* phase, double capacity, double source, const char* dt) {
    return fmt::format(
        "kind: test_participant\ndt: {}\nmesh: {{dim: 1, origin: [0.0], spacing: [0.25], cells: "
        "[4]}}\nwrites:\n  - {{name: {}_temperature, unit: K, function: [{}, 0, 0, 0, 0]}}\n"
        "  - {{name: {}_heat_capacity, unit: J/(m^3 K), function: [{}, 0, 0, 0, 0]}}\n"
        "reads:\n  - {{name: heat_exchange_energy, unit: J, quantity: extensive, time: "
        "integral}}\ndynamics: {{velocity: {}_temperature, impulse: heat_exchange_energy, "
        "bulk_density: {}, body_force: [{}]}}\n",
        dt, phase, heat_t0, phase, capacity, phase, capacity, source);
  };
  write_text(dir / "water.yaml", side("fluid", heat_c_f, heat_source, "1.0e-3"));
  write_text(dir / "rock.yaml", side("solid", heat_c_s, 0.0, "7.0e-4"));
}

}  // namespace cosim::testing
