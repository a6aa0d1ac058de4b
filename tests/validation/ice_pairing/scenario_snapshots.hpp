#pragma once

// Reading back the snapshots of an MPM <-> ICE job for the scenario
// validations (debris flow, submarine landslide): the particles of
// mpm_solver (soil/particles_*.h5) and the cells of ice_fluid
// (water/ice_*.h5), by time.
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "hdf5_reader.hpp"

namespace cosim::testing {

struct ParticleSnapshot {
  double time = 0.0;
  std::vector<double> x, y;    // positions [m]
  std::vector<double> x0, y0;  // initial positions (position - displacement) [m]
  std::vector<int> body;       // index of the body in the case
  std::vector<double> plastic_strain, pore_pressure;
  std::vector<double> mean_effective_stress;  // -tr(sigma') / 3 [Pa]
};

struct CellSnapshot {
  double time = 0.0;
  int nx = 0, ny = 0;                        // cells; values row-major with x fastest
  std::vector<double> pressure, water, air;  // [Pa], volume fractions
  double at(const std::vector<double>& field, int i, int j) const {
    return field[static_cast<std::size_t>(j * nx + i)];
  }
};

inline double rounded_time(double t) {
  return std::round(t * 1e6) / 1e6;
}

inline std::map<double, ParticleSnapshot> particle_snapshots(const std::filesystem::path& dir) {
  std::map<double, ParticleSnapshot> out;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("particles_", 0) != 0 || entry.path().extension() != ".h5") continue;
    Hdf5Reader file(entry.path());
    ParticleSnapshot s;
    s.time = file.root_double("time");
    const auto xyz = file.doubles("geometry/xyz");
    const std::size_t n = xyz.dims[0], c = xyz.dims[1];
    const auto body = file.doubles("fields/body");
    const auto plastic = file.doubles("fields/plastic_strain");
    const auto pore = file.doubles("fields/pore_pressure");
    const auto sigma = file.doubles("fields/effective_stress");
    const auto displacement = file.doubles("fields/displacement");
    for (std::size_t p = 0; p < n; ++p) {
      s.x.push_back(xyz.values[p * c]);
      s.y.push_back(xyz.values[p * c + 1]);
      s.x0.push_back(s.x.back() - displacement.values[p * 3]);
      s.y0.push_back(s.y.back() - displacement.values[p * 3 + 1]);
      s.body.push_back(static_cast<int>(std::lround(body.values[p])));
      s.plastic_strain.push_back(plastic.values[p]);
      s.pore_pressure.push_back(pore.values[p]);
      s.mean_effective_stress.push_back(
          -(sigma.values[p * 6] + sigma.values[p * 6 + 1] + sigma.values[p * 6 + 2]) / 3.0);
    }
    out[rounded_time(s.time)] = std::move(s);
  }
  return out;
}

inline std::map<double, CellSnapshot> cell_snapshots(const std::filesystem::path& dir) {
  std::map<double, CellSnapshot> out;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("ice_", 0) != 0 || entry.path().extension() != ".h5") continue;
    Hdf5Reader file(entry.path());
    CellSnapshot s;
    s.time = file.root_double("time");
    auto pressure = file.doubles("fields/pressure");
    s.ny = static_cast<int>(pressure.dims[0]);
    s.nx = static_cast<int>(pressure.dims[1]);
    s.pressure = std::move(pressure.values);
    s.water = file.doubles("fields/volume_fraction_water").values;
    s.air = file.doubles("fields/volume_fraction_air").values;
    out[rounded_time(s.time)] = std::move(s);
  }
  return out;
}

}  // namespace cosim::testing
