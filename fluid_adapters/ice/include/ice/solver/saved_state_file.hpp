#pragma once

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

}  // namespace ice
