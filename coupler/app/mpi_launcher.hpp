#pragma once

#include "job/job.hpp"
#include "run_command.hpp"
#include "runtime/mpi_launch.hpp"

// `cosim run` of an MPI job, outside mpirun: starts mpirun with the job's
// MPMD line and watches it. mpirun and MPI cannot always end a job that
// fails: a rank stopped or stuck before MPI_Init holds every other rank in
// MPI_Init, one stopped after the run holds the others in MPI_Finalize, and
// a rank that dies takes the coupler rank with it before it can write its
// record. So this process keeps its own deadlines (admission within the
// connect timeout, exit within window_timeout after the run), stops the
// whole job when one passes, names the participant at fault, and finishes
// the run's summary.json.
namespace cosim::app {

// Returns the exit code of the run.
int launch_mpirun(const job::Job& job, const RunOptions& options);

// The checkpoint options of `options` an MPI job's applications take.
runtime::CheckpointArguments checkpoint_arguments(const RunOptions& options);

}  // namespace cosim::app
