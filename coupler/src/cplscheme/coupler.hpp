#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosim::cplscheme
