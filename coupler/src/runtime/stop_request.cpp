#include "cosim/runtime/stop_request.hpp"

#include <fmt/format.h>

#include <csignal>
#include <cstring>

#include "cosim/error.hpp"

namespace cosim::runtime {

namespace {

std::atomic<int> requested_by{0};
std::atomic<bool> requested{false};

void on_stop_signal(int signal) {
  int none = 0;
  requested_by.compare_exchange_strong(none, signal);
  requested = true;
}

}  // namespace

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  for (int signal : {SIGTERM, SIGINT, SIGHUP}) sigaction(signal, &action, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
}

int stop_signal() {
  return requested_by.load();
}

const std::atomic<bool>& stop_flag() {
  return requested;
}

std::string describe_stop() {
  const int signal = stop_signal();
  return fmt::format("stopped by signal {} ({})", signal, ::strsignal(signal));
}

void throw_if_stop_requested() {
  if (stop_requested()) throw Error(ExitCode::participant_failed, describe_stop());
}

}  // namespace cosim::runtime
