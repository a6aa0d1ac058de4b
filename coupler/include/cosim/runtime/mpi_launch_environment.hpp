#pragma once

#include <string>
#include <vector>

// What mpirun or srun leave in the environment of the ranks they start.
namespace cosim::runtime {

// Whether this process was started as a rank of an MPI job (Open MPI's,
// PMI's or PMIx's variables are set).
bool launched_as_mpi_rank();

// The prefixes of those variables: a child that must not join this
// process's MPI job (an MPI program of its own) is started without them.
const std::vector<std::string>& mpi_launch_variable_prefixes();

}  // namespace cosim::runtime
