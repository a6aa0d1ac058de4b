#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "com/transport.hpp"

// MPI transport for one MPMD launch:
//   mpirun -np 1 cosim run job.yaml ... : -np 1 <solver> ... : -np 1 <solver> ...
// The coupler is world rank 0 (the first application). MPI_COMM_WORLD is
// split by MPMD application number so each participant owns a communicator
// for its own parallel work; coupling messages travel on a duplicate of
// MPI_COMM_WORLD so they never mix with a solver's traffic.
namespace cosim::com {

class MpiHub final : public Hub {
 public:
  // The peer the mpirun line starts at each world rank from 1 on, in order:
  // a participant's name, or for one on several ranks its parts' names
  // (runtime::part_peer_name); a rank is admitted as that peer only.
  explicit MpiHub(std::vector<std::string> participants);
  ~MpiHub() override;
  MpiHub(const MpiHub&) = delete;
  MpiHub& operator=(const MpiHub&) = delete;

  int world_size() const;
  // The participant the launch line starts at `rank`; empty for rank 0 and
  // ranks beyond the job's.
  std::string participant_of_rank(int rank) const;
  // Ends every process of the MPI job with `exit_code` (MPI_Abort): after a
  // failure the other ranks may never reach MPI_Finalize (a stopped or hung
  // participant), which would block this one forever.
  [[noreturn]] void abort_job(int exit_code);

  void admit(const std::string& connection, const std::string& participant) override;
  void send(const std::string& peer, const Message& message) override;
  std::optional<Received> receive(std::chrono::milliseconds timeout) override;
  std::string describe() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class MpiClient final : public Transport {
 public:
  explicit MpiClient(const std::string& participant_name);
  ~MpiClient() override;
  MpiClient(const MpiClient&) = delete;
  MpiClient& operator=(const MpiClient&) = delete;

  void send(const std::string& peer, const Message& message) override;
  std::optional<Received> receive(std::chrono::milliseconds timeout) override;
  std::string describe() const override;
  // This rank and the number of ranks of this program (its own communicator,
  // MPI_COMM_WORLD split by the launch line's applications).
  int application_rank() const;
  int application_size() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosim::com
