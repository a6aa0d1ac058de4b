#include "cosim/runtime/mpi_session.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "cosim/error.hpp"
#include "cosim/runtime/application_communicator.hpp"

namespace cosim::runtime {

int ranks_from_launcher() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(variable)) return std::max(1, std::atoi(value));
  return 1;
}

MpiSession::MpiSession() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  comm_ = application_communicator();
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &ranks_);
}

MpiSession::~MpiSession() {
  MPI_Finalize();
}

int MpiSession::finish(int code, std::chrono::milliseconds grace) const {
  MPI_Request all_ended = MPI_REQUEST_NULL;
  MPI_Ibarrier(comm_, &all_ended);
  const auto deadline = std::chrono::steady_clock::now() + grace;
  for (int ended = 0;;) {
    MPI_Test(&all_ended, &ended, MPI_STATUS_IGNORE);
    if (ended) break;
    if (code != 0 && std::chrono::steady_clock::now() > deadline) {
      MPI_Abort(MPI_COMM_WORLD, code);
      std::_Exit(code);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  int job = code;
  MPI_Allreduce(&code, &job, 1, MPI_INT, MPI_MAX, comm_);
  // A participant of an MPMD job that failed before every rank said hello
  // to the coupler: the coupler still waits for it, and MPI_Finalize would
  // wait for the coupler. The job ends here, with this program's code.
  int world = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &world);
  int all_said_hello = hello_sent() ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &all_said_hello, 1, MPI_INT, MPI_MIN, comm_);
  if (job != 0 && world > ranks_ && !all_said_hello) {
    if (rank_ == 0)
      std::fprintf(stderr,
                   "this program failed (exit code %d) before the coupler heard of it: the MPI "
                   "job stops\n",
                   job);
    MPI_Abort(MPI_COMM_WORLD, job);
    std::_Exit(job);
  }
  return job;
}

int MpiSession::finish_run(std::string_view program, const std::function<int()>& run) const {
  int code = 0;
  try {
    code = run();
  } catch (const Error& e) {
    std::fprintf(stderr, "%s: %s\n", std::string(program).c_str(), e.what());
    code = to_int(e.code());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", std::string(program).c_str(), e.what());
    code = to_int(ExitCode::internal_error);
  }
  return finish(code);
}

RankOutput prepare_rank_output(const MpiSession& mpi, const std::filesystem::path& output,
                               OutputReuse reuse, Verbosity verbosity, std::string_view program) {
  RankOutput mine{0, output, verbosity};
  if (mpi.rank() == 0) {
    try {
      prepare_output_directory(output, reuse);
    } catch (const Error& e) {
      std::fprintf(stderr, "%s: %s\n", std::string(program).c_str(), e.what());
      mine.refused = to_int(e.code());
    }
  }
  MPI_Bcast(&mine.refused, 1, MPI_INT, 0, mpi.comm());
  if (mine.refused != 0 || mpi.rank() == 0) return mine;
  mine.directory = output / "ranks" / fmt::format("rank_{}", mpi.rank());
  create_output_directory(mine.directory);
  mine.verbosity = Verbosity::quiet;
  return mine;
}

}  // namespace cosim::runtime
