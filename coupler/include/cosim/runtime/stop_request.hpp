#pragma once

#include <atomic>
#include <string>

// A polite stop: SIGTERM, SIGINT and SIGHUP only record that the process was
// asked to stop; the program notices it between steps (the participant API
// checks it in advance() and while it waits for the coupler) and ends the
// way it ends on an error, so its summary.json and log say why it stopped.
namespace cosim::runtime {

// Installs the handlers (and ignores SIGPIPE); call once, early in main.
void install_stop_handlers();

// The signal that asked this process to stop, or 0.
int stop_signal();
inline bool stop_requested() {
  return stop_signal() != 0;
}

// True once a stop was requested; for APIs that watch an atomic flag.
const std::atomic<bool>& stop_flag();

// "stopped by signal 15 (Terminated)".
std::string describe_stop();

// Throws cosim::Error (participant_failed) saying which signal, when a stop
// was requested.
void throw_if_stop_requested();

}  // namespace cosim::runtime
