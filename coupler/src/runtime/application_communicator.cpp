#include "cosim/runtime/application_communicator.hpp"

#include <algorithm>
#include <cstdlib>

namespace cosim::runtime {

namespace {

bool said_hello = false;

int application_index() {
  int* appnum = nullptr;
  int flag = 0;
  MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_APPNUM, &appnum, &flag);
  if (flag && appnum != nullptr) return *appnum;
  if (const char* index = std::getenv("COSIM_APP_INDEX")) return std::max(0, std::atoi(index));
  return 0;
}

}  // namespace

MPI_Comm application_communicator() {
  static const MPI_Comm communicator = [] {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm split = MPI_COMM_NULL;
    MPI_Comm_split(MPI_COMM_WORLD, application_index(), rank, &split);
    return split;
  }();
  return communicator;
}

void note_hello_sent() {
  said_hello = true;
}

bool hello_sent() {
  return said_hello;
}

}  // namespace cosim::runtime
