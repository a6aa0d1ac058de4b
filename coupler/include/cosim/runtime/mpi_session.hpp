#pragma once

#include <mpi.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <string_view>

#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"

// A solver started by `mpirun -np N` on its own (issue 27): whether it was,
// and MPI for the run, with an end that no rank can leave hanging.
namespace cosim::runtime {

// The ranks mpirun started (from its environment, before MPI starts); 1
// outside mpirun.
int ranks_from_launcher();

// MPI for the run: initialised by the constructor, finalised by the
// destructor.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  // This program's ranks: MPI_COMM_WORLD, or within an MPMD job (a coupled
  // participant on several ranks) this program's share of it.
  MPI_Comm comm() const { return comm_; }
  int rank() const { return rank_; }
  int ranks() const { return ranks_; }
  // The end of the run on this rank with exit code `code`: waits for every
  // rank to end and returns the largest code. A rank that failed waits at
  // most `grace` for the others, then ends them all with its code
  // (MPI_Abort): failing alone, it would leave them waiting in a
  // collective forever.
  int finish(int code, std::chrono::milliseconds grace = std::chrono::seconds(2)) const;
  // finish() with the code `run` returns, or that of the cosim::Error it
  // throws (its message printed as "<program>: <message>"; 1 for any other
  // exception): no failure skips the end above.
  int finish_run(std::string_view program, const std::function<int()>& run) const;

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, ranks_ = 1;
};

// Where one rank of a run that writes one set of files keeps its own log
// and summary: rank 0 prepares `output` (as `reuse` allows) and keeps them
// there; rank r > 0 keeps them, quiet on the console, in
// output/ranks/rank_<r>/. `refused` is the exit code of an output directory
// rank 0 could not prepare (0 when ready): every rank learns it, and then
// nothing is written (collective).
struct RankOutput {
  int refused = 0;
  std::filesystem::path directory;
  Verbosity verbosity = Verbosity::normal;
};
RankOutput prepare_rank_output(const MpiSession& mpi, const std::filesystem::path& output,
                               OutputReuse reuse, Verbosity verbosity, std::string_view program);

}  // namespace cosim::runtime
