#include "progress.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>

namespace cosim::cplscheme {

namespace {

std::string clock_text(double seconds) {
  const auto s = static_cast<long>(seconds + 0.5);
  return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}

}  // namespace

Progress::Progress(double start_time, double end_time, std::size_t windows, bool terminal)
    : start_time_(start_time),
      end_time_(end_time),
      windows_(windows),
      terminal_(terminal),
      started_(std::chrono::steady_clock::now()),
      last_report_(started_) {}

void Progress::update(std::size_t window, double time, std::size_t iterations) {
  const auto now = std::chrono::steady_clock::now();
  const double wall = std::chrono::duration<double>(now - started_).count();
  const double done = (time - start_time_) / (end_time_ - start_time_);
  const double eta = done > 0.0 ? wall * (1.0 - done) / done : 0.0;
  const std::string line = fmt::format(
      "t = {:.6g} s ({:5.1f} %)  window {}/{}{}  wall {}  ETA {}", time, 100.0 * done, window,
      windows_, iterations ? fmt::format(" ({} iterations)", iterations) : std::string(),
      clock_text(wall), clock_text(eta));
  if (terminal_) {
    std::fprintf(stderr, "\r%s\033[K", line.c_str());
    std::fflush(stderr);
  } else if (now - last_report_ >= std::chrono::seconds(10)) {
    spdlog::info("{}", line);
    last_report_ = now;
  }
}

void Progress::finish() {
  if (terminal_) std::fprintf(stderr, "\n");
}

}  // namespace cosim::cplscheme
