#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "cosim/decomposition/block_join.hpp"
#include "cosim/io/state_file.hpp"
#include "ice/solver/saved_state.hpp"

// A SavedIceState in a checkpoint's state file (architecture.md §14): every
// array under its name (`fluid.pressure`, `material.1.velocity.0`,
// `face_velocity.0.1`, ...) and the scalars, read back bit for bit. The
// restarted solver takes it with IceSolver::restore_state.
namespace ice {

template <int Dim>
void write_saved_state(cosim::StateFileWriter& out, const SavedIceState<Dim>& state);

// `cells`: the case's cell count, which the cell fields must have (a state
// of another grid is refused, exit 2).
template <int Dim>
void read_saved_state(const cosim::StateFileReader& in, std::size_t cells,
                      SavedIceState<Dim>& state);

// The states the blocks `from` of another decomposition of the case's grid
// (grid_cells cells) wrote into `parts`, joined into the block `to`
// (restart on another count of ranks): each cell's and each face's values
// from a block that owns it (a block owns the faces of its cells, its upper
// ones shared with the next block), the scalars from the first part.
// Throws cosim::InputError when the parts do not cover the block.
template <int Dim>
void read_saved_state(std::span<const cosim::StateFileReader* const> parts,
                      std::span<const cosim::decomposition::StoredBlock> from,
                      const std::array<std::int64_t, 3>& grid_cells,
                      const cosim::decomposition::StoredBlock& to, SavedIceState<Dim>& state);

}  // namespace ice
