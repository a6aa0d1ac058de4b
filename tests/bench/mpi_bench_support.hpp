#pragma once

// What the MPI benchmarks (swe_2d_mpi_bench, mpm_mpi_bench) share: the
// slowest rank's figure and the median of the repetitions.
#include <mpi.h>

#include <algorithm>
#include <vector>

namespace bench {

inline double max_over_ranks(double value) {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return value;
}

inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace bench
