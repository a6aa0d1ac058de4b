#pragma once

#include <span>

#include "cosim/io/state_file.hpp"
#include "mpm/particles/particles.hpp"

// Every particle array in a checkpoint's state file (`particles.<quantity>`),
// read back bit for bit (architecture.md §14).
namespace mpm {

template <int Dim>
void write_particles(cosim::StateFileWriter& out, const Particles<Dim>& particles);

// Into particles of the count the case seeds: a file of another count or
// dimension is refused (exit 2) naming the array.
template <int Dim>
void read_particles(const cosim::StateFileReader& in, Particles<Dim>& particles);

// Every point of the `parts` (the files of a checkpoint's ranks, or some of
// them), in id order: the count is the files'.
template <int Dim>
void read_particles(std::span<const cosim::StateFileReader* const> parts,
                    Particles<Dim>& particles);

}  // namespace mpm
