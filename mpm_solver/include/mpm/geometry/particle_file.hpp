#pragma once

#include <map>
#include <string>
#include <vector>

#include "mpm/geometry/seeded_particles.hpp"

namespace mpm {

// Particles listed in a CSV text file:
//
//   x,y[,z],volume[,more columns...]
//   0.05,0.05,0.0025
//   ...
//
// The header names the columns (any order, surrounding blanks ignored); x,
// y, volume (and z in 3D) are required. Blank lines and lines starting with
// '#' are skipped. Every value must be a finite number and every volume
// positive. Other columns are returned by name. Half-lengths are
// 0.5 volume^(1/Dim) in every direction.
template <int Dim>
struct ParticleFile {
  SeededParticles<Dim> particles;
  std::map<std::string, std::vector<double>> extra_columns;
};

// Throws cosim::InputError naming the file, line and column of the first
// problem: unreadable file, missing or repeated header column, wrong number
// of values, a value that is not a finite number, a non-positive volume, no
// particles.
template <int Dim>
ParticleFile<Dim> read_particle_file(const std::string& path);

}  // namespace mpm
