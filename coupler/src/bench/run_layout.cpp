#include "bench/run_layout.hpp"

#include <fmt/format.h>

#include "bench/pairing.hpp"
#include "cosim/config/document.hpp"
#include "cosim/error.hpp"

namespace cosim::bench {

namespace fs = std::filesystem;

fs::path RunLayout::participant(const std::string& name) const {
  return coupled && !name.empty() ? output / name : output;
}

fs::path RunLayout::fluid(const std::string& name) const {
  return participant(name.empty() ? std::string(fluid_participant) : name);
}

fs::path RunLayout::soil_case(const std::string& participant) const {
  if (!coupled) return input / "case.yaml";
  // The job names the participant's config (absolute in the run's copy).
  const auto job = config::Document::load_file(input / "job.yaml");
  const YAML::Node config = job.root().yaml()["participants"][participant]["config"];
  if (!config)
    throw Error(ExitCode::bad_input,
                fmt::format("{}: no participant '{}' with a config (give the soil's participant)",
                            (input / "job.yaml").string(), participant));
  return config.as<std::string>();
}

namespace {

[[noreturn]] void not_recorded(Backend backend, const std::string& what) {
  throw Error(ExitCode::bad_input,
              fmt::format("the {} backend does not record {}", to_string(backend), what));
}

}  // namespace

std::string gauge_file(Backend backend) {
  return backend == Backend::mpm ? "probes.csv" : "gauges.csv";
}

std::string gauge_column(Backend backend, const std::string& g, const std::string& variable) {
  switch (backend) {
    case Backend::ice:
      if (variable == "pressure") return fmt::format("p_{} [Pa]", g);
      if (variable == "velocity_x") return fmt::format("ux_{} [m/s]", g);
      if (variable == "velocity_y") return fmt::format("uy_{} [m/s]", g);
      if (variable == "velocity_z") return fmt::format("uz_{} [m/s]", g);
      if (variable == "water_fraction") return fmt::format("phi_water_{} [1]", g);
      break;
    case Backend::openfoam:
      if (variable == "pressure") return fmt::format("{}_p [Pa]", g);
      if (variable == "velocity_x") return fmt::format("{}_ux [m/s]", g);
      if (variable == "velocity_y") return fmt::format("{}_uy [m/s]", g);
      if (variable == "velocity_z") return fmt::format("{}_uz [m/s]", g);
      if (variable == "water_fraction") return fmt::format("{}_water_fraction [1]", g);
      if (variable == "surface_elevation") return fmt::format("{}_surface_elevation [m]", g);
      break;
    case Backend::swe:
      if (variable == "surface_elevation") return fmt::format("eta_{} [m]", g);
      if (variable == "depth") return fmt::format("h_{} [m]", g);
      if (variable == "speed") return fmt::format("speed_{} [m/s]", g);
      break;
    case Backend::mpm:
      if (variable == "pressure") return fmt::format("{}_pore_pressure [Pa]", g);
      if (variable == "velocity_x") return fmt::format("{}_velocity_x [m/s]", g);
      if (variable == "velocity_y") return fmt::format("{}_velocity_y [m/s]", g);
      if (variable == "velocity_z") return fmt::format("{}_velocity_z [m/s]", g);
      break;
    case Backend::coupler: break;
  }
  not_recorded(backend, "gauge variable '" + variable + "'");
}

std::string snapshot_base(Backend backend) {
  switch (backend) {
    case Backend::ice: return "ice";
    case Backend::openfoam: return "openfoam";
    case Backend::swe: return "swe";
    case Backend::mpm: return "particles";
    case Backend::coupler: break;
  }
  not_recorded(backend, "field snapshots of its own");
}

StoredField stored_field(Backend backend, const std::string& field) {
  if (field == "velocity_x") return {"velocity", 0};
  if (field == "velocity_y") return {"velocity", 1};
  switch (backend) {
    case Backend::ice:
      if (field == "pressure" || field == "density") return {field, 0};
      if (field == "temperature") return {"temperature_water", 0};
      if (field == "water_fraction") return {"volume_fraction_water", 0};
      break;
    case Backend::openfoam:
      if (field == "pressure") return {"pressure", 0};
      if (field == "water_fraction") return {"alpha_water", 0};
      break;
    case Backend::swe:
      if (field == "depth") return {"h", 0};
      if (field == "free_surface") return {"eta", 0};
      break;
    case Backend::mpm:
      if (field == "pressure") return {"pore_pressure", 0};
      break;
    case Backend::coupler: break;
  }
  not_recorded(backend, "the field '" + field + "'");
}

}  // namespace cosim::bench
