#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "checkpoint/schedule.hpp"
#include "com/transport.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/runtime/supervisor.hpp"
#include "job/job.hpp"

// The coupler's side of a coupled run: admits the participants (handshake),
// then, window after window, collects what each wrote, maps every exchange
// onto the receiving mesh and sends it on (architecture.md §3).
namespace cosim::cplscheme {

struct CouplerOptions {
  std::filesystem::path output_dir;
  std::string job_id;
  double connect_timeout_s = 120.0;  // for every participant's hello
  bool progress_on_terminal = false;
  // Set by a signal handler to stop the run between messages.
  const std::atomic<bool>* interrupted = nullptr;
  // Participant name -> the run token handed to its process; when given, a
  // hello is admitted only with its participant's token.
  std::map<std::string, std::string> tokens;
  // How long a participant that reported its own failure may take to finish
  // its record (summary.json, log) and exit, before the run is stopped.
  std::chrono::milliseconds failure_grace{5000};
  // Checkpoints of the coupled run (architecture.md §14): when, how many kept.
  std::optional<checkpoint::Schedule> checkpoint_every;
  std::size_t checkpoints_kept = 2;
  // A checkpoint (its manifest already checked) to continue from, and the
  // window it holds.
  std::filesystem::path restart;
  std::size_t restart_window = 0;
};

class Coupler {
 public:
  // `supervisor` watches the participants' processes; null under mpirun,
  // which does that itself.
  Coupler(const job::Job& job, com::Hub& transport, runtime::Supervisor* supervisor,
          RunSummary& summary, CouplerOptions options);
  ~Coupler();
  Coupler(const Coupler&) = delete;
  Coupler& operator=(const Coupler&) = delete;

  // Runs to the job's end time. Throws cosim::Error (with its exit code) on
  // failure, after telling every connected participant to abort.
  void run();
  // Whether run() ended early at a checkpoint because a stop was requested
  // (the participants finish by themselves after writing their parts).
  bool stopped_at_checkpoint() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosim::cplscheme
