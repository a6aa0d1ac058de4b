#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

// The MPM soil as MPPICInterFoam's kinematic cloud, in "cell mode": one
// parcel at the centre of every cell holding soil, re-created at the start
// of every window, with the cell's solid velocity and as many grains of one
// diameter as fill the cell's solid volume (nParticle = phi_s V / (pi d^3 / 6)).
// The parcels' immense density keeps the drag from changing their velocity
// within a window; without a gravity force they carry no weight (the MPM
// does), so OpenFOAM's p is the pore pressure.
namespace openfoam {

struct SoilParcels {
  std::vector<double> position;    // x, y, z per parcel [m]
  std::vector<std::int64_t> cell;  // the cell holding it
  std::vector<double> velocity;    // x, y, z per parcel [m/s]
  std::vector<double> diameter;    // d [m]
  std::vector<double> grains;      // nParticle
  std::size_t size() const { return cell.size(); }
  void clear();
  void add(const double* centre, std::int64_t cell_index, const double* velocity, double d,
           double grain_count);
};

// The cloud's name in MPPICInterFoam and its parcel class.
inline constexpr const char* cloud_name = "kinematicCloud";
inline constexpr const char* parcel_class = "basicKinematicMPPICParcel";

// Replaces the cloud of the time directory `time_dir` (named `time_name`):
// `positions` and every per-parcel list, each file atomically, the stale
// barycentric `coordinates` removed, and `uniform/lagrangian/<cloud>/
// cloudProperties` saying `geometry positions`. No parcels: the cloud's
// directory is removed.
void write_soil_cloud(const std::filesystem::path& time_dir, std::string_view time_name,
                      const SoilParcels& parcels, double parcel_density);

}  // namespace openfoam
