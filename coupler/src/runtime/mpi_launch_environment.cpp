#include "cosim/runtime/mpi_launch_environment.hpp"

#include <cstdlib>

namespace cosim::runtime {

bool launched_as_mpi_rank() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_RANK", "PMIX_RANK"})
    if (std::getenv(variable) != nullptr) return true;
  return false;
}

const std::vector<std::string>& mpi_launch_variable_prefixes() {
  static const std::vector<std::string> prefixes{"OMPI_", "PMIX_", "PMI_"};
  return prefixes;
}

}  // namespace cosim::runtime
