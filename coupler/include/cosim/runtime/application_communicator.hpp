#pragma once

#include <mpi.h>

// One program's ranks within an MPMD job (a coupled participant on several
// ranks), or MPI_COMM_WORLD's ranks for a program started alone.
namespace cosim::runtime {

// MPI_COMM_WORLD split by the program's place on the launch line (mpirun's
// MPI_APPNUM, or under srun --multi-prog, which has none, COSIM_APP_INDEX).
// Made once per process, on first use, and shared by the solver and the
// MPI transport: every program of the job calls MPI_Comm_split on
// MPI_COMM_WORLD exactly once, so their collectives on it stay matched.
// MPI must be initialised; the communicator lives until MPI_Finalize.
MPI_Comm application_communicator();

// Whether this process has said hello to the coupler over MPI: from then on
// the coupler hears of its failure through the protocol (an abort message).
// A program of an MPMD job that fails before it stops the MPI job itself
// (MpiSession::finish): the coupler would wait for its hello in vain.
void note_hello_sent();
bool hello_sent();

}  // namespace cosim::runtime
