#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "cosim/config/schema.hpp"
#include "cosim/error.hpp"
#include "cosim/io/run_size.hpp"
#include "mpm/depth_averaged/depth_averaged_material.hpp"
#include "mpm/depth_averaged/depth_averaged_particles.hpp"
#include "mpm/depth_averaged/depth_averaged_solver.hpp"

namespace mpm {

// A point whose depth and speed the run records in gauges.csv.
struct DepthGauge {
  std::string name;
  Vec<2> position;
};

// A `kind: depth_averaged_case` file, read and checked: the depth-averaged
// mass of van den Bout et al. (OpenLISEM Hazard) over a terrain, standalone.
struct DepthAveragedCase {
  std::string name;
  std::filesystem::path file;
  std::uint64_t config_hash = 0;
  DepthAveragedSettings settings;
  // Where terrain.inclination is (or would be) in the file, for a coupled
  // run that refuses an inclined plane.
  cosim::SourceLocation inclination_where;
  std::vector<DepthAveragedMaterial> materials;
  std::vector<std::string> mass_names;  // one per `masses` entry
  DepthAveragedParticles particles;     // seeded
  double end_time = 0.0;
  double output_every = 0.0;  // snapshots; 0: first and last only
  double gauge_every = 0.0;   // gauge rows; 0: at every snapshot
  std::vector<DepthGauge> gauges;
  int threads = 0;
  cosim::RunSize size;
};

// The keys of the file: the one place they are documented.
cosim::config::Schema depth_averaged_case_schema();
std::string depth_averaged_case_help();

// Reads, checks and seeds a case. Every problem is a cosim::InputError
// naming the file, key and line (a raster's own problems name the raster's
// file and line): unknown keys, values out of range, a material or mass that
// does not exist, a mass or gauge outside the grid, a raster that does not
// cover the grid (bed) or its mass (depth), a negative depth, a mass that
// seeds no point. Relative paths resolve from the file's directory.
DepthAveragedCase load_depth_averaged_case(const std::filesystem::path& file);
// Whether `file` says `kind: depth_averaged_case` (false when it cannot be
// read: the loader of the other kind then says why).
bool is_depth_averaged_case(const std::filesystem::path& file);
DepthAveragedCase load_depth_averaged_case_text(std::string_view text,
                                                const std::filesystem::path& name);

}  // namespace mpm
