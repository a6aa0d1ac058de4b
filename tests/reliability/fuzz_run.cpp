#include "fuzz_run.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>
#include <typeinfo>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/common_interface_defs.h>
#endif

#include "cosim/error.hpp"
#include "mutator.hpp"
#include "text_files.hpp"

namespace cosim::testing {

namespace {

namespace fs = std::filesystem;

constexpr char base64_digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// The four base64 digits of the bytes at `i`, `i + 1`, `i + 2` (padded
// past `size`).
std::array<char, 4> base64_group(const char* data, std::size_t size, std::size_t i) {
  const auto byte = [&](std::size_t k) -> std::uint32_t {
    return k < size ? static_cast<unsigned char>(data[k]) : 0u;
  };
  const std::uint32_t group = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
  return {base64_digits[(group >> 18) & 63], base64_digits[(group >> 12) & 63],
          i + 1 < size ? base64_digits[(group >> 6) & 63] : '=',
          i + 2 < size ? base64_digits[group & 63] : '='};
}

// Written with write(2) only: the crash report runs inside a signal handler.
void write_base64(int fd, const char* data, std::size_t size) {
  std::array<char, 1024> out{};
  std::size_t used = 0;
  for (std::size_t i = 0; i < size; i += 3) {
    const auto group = base64_group(data, size, i);
    std::memcpy(out.data() + used, group.data(), group.size());
    used += group.size();
    if (used == out.size()) {
      (void)!::write(fd, out.data(), used);
      used = 0;
    }
  }
  (void)!::write(fd, out.data(), used);
}

std::string base64(const std::string& data) {
  std::string out;
  for (std::size_t i = 0; i < data.size(); i += 3) {
    const auto group = base64_group(data.data(), data.size(), i);
    out.append(group.data(), group.size());
  }
  return out;
}

std::uint64_t fnv1a(const char* data, std::size_t size) {
  std::uint64_t hash = 0xcbf29ce484222325;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(data[i]);
    hash *= 0x100000001b3;
  }
  return hash;
}

std::uint64_t environment_number(const char* name, std::uint64_t fallback) {
  const char* value = std::getenv(name);
  return value && *value ? std::stoull(value) : fallback;
}

// What the crash report needs, set before each input runs.
struct InFlight {
  const char* target = "";
  const char* data = nullptr;
  std::size_t size = 0;
  std::array<char, 4096> save_directory{};  // empty: do not save
  std::atomic<bool> reported{false};
};
InFlight in_flight;

void report_input_in_flight(const char* why) {
  if (in_flight.data == nullptr || in_flight.reported.exchange(true)) return;
  const auto say = [](const char* text) { (void)!::write(2, text, std::strlen(text)); };
  say("\nfuzz: ");
  say(in_flight.target);
  say(": ");
  say(why);
  say(" on this input (base64): ");
  write_base64(2, in_flight.data, in_flight.size);
  say("\n");
  if (in_flight.save_directory[0] == '\0') return;
  // <dir>/crash-<fnv1a hex>
  std::array<char, 4200> path{};
  std::size_t n = std::strlen(in_flight.save_directory.data());
  std::memcpy(path.data(), in_flight.save_directory.data(), n);
  std::memcpy(path.data() + n, "/crash-", 7);
  n += 7;
  const std::uint64_t hash = fnv1a(in_flight.data, in_flight.size);
  for (int shift = 60; shift >= 0; shift -= 4) path[n++] = "0123456789abcdef"[(hash >> shift) & 15];
  const int fd = ::open(path.data(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return;
  (void)!::write(fd, in_flight.data, in_flight.size);
  ::close(fd);
  say("fuzz: saved as ");
  say(path.data());
  say("\n");
}

constexpr std::array<int, 5> crash_signals{SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
std::array<struct sigaction, 5> previous_actions{};

void on_crash_signal(int signal) {
  report_input_in_flight("crashed");
  for (std::size_t i = 0; i < crash_signals.size(); ++i)
    if (crash_signals[i] == signal) ::sigaction(signal, &previous_actions[i], nullptr);
  // Returning re-runs the faulting instruction (or abort() raises again):
  // the previous handler (the sanitizer's, or the default) then reports.
}

// Installs the crash report for the duration of a run, on a stack of its
// own (a stack overflow leaves none).
class CrashReport {
 public:
  CrashReport() {
    stack_.resize(1 << 18);
    stack_t alternate{};
    alternate.ss_sp = stack_.data();
    alternate.ss_size = stack_.size();
    ::sigaltstack(&alternate, &previous_stack_);
    struct sigaction action {};
    action.sa_handler = on_crash_signal;
    action.sa_flags = SA_ONSTACK;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < crash_signals.size(); ++i)
      ::sigaction(crash_signals[i], &action, &previous_actions[i]);
#if defined(__SANITIZE_ADDRESS__)
    __sanitizer_set_death_callback([] { report_input_in_flight("failed a sanitizer check"); });
#endif
  }
  ~CrashReport() {
    for (std::size_t i = 0; i < crash_signals.size(); ++i)
      ::sigaction(crash_signals[i], &previous_actions[i], nullptr);
    ::sigaltstack(&previous_stack_, nullptr);
#if defined(__SANITIZE_ADDRESS__)
    __sanitizer_set_death_callback(nullptr);
#endif
    in_flight.data = nullptr;
  }
  CrashReport(const CrashReport&) = delete;
  CrashReport& operator=(const CrashReport&) = delete;

 private:
  std::vector<char> stack_;
  stack_t previous_stack_{};
};

// Stops the process, with the input printed, when one input runs for much
// longer than the hang limit: an endless loop never returns to be timed.
class Watchdog {
 public:
  explicit Watchdog(std::chrono::milliseconds limit)
      : limit_(limit), thread_([this] { watch(); }) {}
  ~Watchdog() {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  void started() { started_ns_.store(now_ns()); }
  void finished() { started_ns_.store(0); }

 private:
  static std::int64_t now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
  void watch() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop_; })) {
      const std::int64_t started = started_ns_.load();
      if (started != 0 && now_ns() - started > 30 * std::chrono::nanoseconds(limit_).count()) {
        report_input_in_flight("hung (30 times the hang limit)");
        std::abort();
      }
    }
  }

  std::chrono::milliseconds limit_;
  std::atomic<std::int64_t> started_ns_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

// The CPU time this thread has used: an input is timed by the work it
// causes, not by how long two shared cores left the process waiting (inputs
// that took 1.1-1.2 s of wall time in a benchmark run took 10-20 ms alone).
double thread_cpu_seconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// Runs one input; returns what went wrong, empty when nothing did.
std::string run_one(const FuzzTarget& target, const std::string& input, Watchdog& watchdog,
                    FuzzReport& report) {
  in_flight.data = input.data();
  in_flight.size = input.size();
  std::string failure;
  const double start = thread_cpu_seconds();
  watchdog.started();
  try {
    target.run(input);
  } catch (const cosim::Error&) {
    // the refusal every bad input should get
  } catch (const std::exception& e) {
    failure = fmt::format("threw {} (not a cosim::Error): {}", typeid(e).name(), e.what());
  } catch (...) {
    failure = "threw something that is not a std::exception";
  }
  watchdog.finished();
  in_flight.data = nullptr;
  const double seconds = thread_cpu_seconds() - start;
  report.slowest_seconds = std::max(report.slowest_seconds, seconds);
  if (failure.empty() && seconds > std::chrono::duration<double>(target.hang_limit).count()) {
    failure = fmt::format("took {:.2f} s of CPU time (hang limit {} ms)", seconds,
                          target.hang_limit.count());
    ++report.hangs;
  } else if (!failure.empty()) {
    ++report.crashes;
  }
  return failure;
}

void record(const FuzzTarget& target, const std::string& input, const std::string& failure,
            FuzzReport& report) {
  std::string saved;
  if (in_flight.save_directory[0] != '\0') {
    const fs::path file = fs::path(in_flight.save_directory.data()) /
                          fmt::format("crash-{:016x}", fnv1a(input.data(), input.size()));
    std::ofstream(file, std::ios::binary) << input;
    saved = ", saved as " + file.string();
  }
  report.failures.push_back(fmt::format("{}: {} on this input ({} bytes{}, base64): {}",
                                        target.name, failure, input.size(), saved, base64(input)));
}

}  // namespace

std::string FuzzReport::summary(const std::string& target) const {
  return fmt::format(
      "fuzz {}: {} regression inputs and {} mutated inputs in {:.1f} s ({:.0f} per second); "
      "{} crashes, {} hangs; slowest input {:.3f} s of CPU time",
      target, regression_inputs, executions, seconds,
      seconds > 0 ? static_cast<double>(regression_inputs + executions) / seconds : 0.0, crashes,
      hangs, slowest_seconds);
}

std::vector<fs::path> files_under(const fs::path& directory, const std::string& extension) {
  std::vector<fs::path> files;
  if (!fs::is_directory(directory)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.size() >= extension.size() &&
        name.compare(name.size() - extension.size(), extension.size(), extension) == 0)
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // the same order, hence the same run, everywhere
  return files;
}

std::vector<std::string> regression_inputs(const std::string& target) {
  std::vector<std::string> inputs;
  for (const fs::path& file :
       files_under(fs::path(COSIM_SOURCE_DIR) / "tests" / "data" / "fuzz" / target, ""))
    inputs.push_back(read_text(file));
  return inputs;
}

FuzzReport fuzz(const FuzzTarget& target) {
  FuzzReport report;
  in_flight.target = target.name.c_str();
  in_flight.reported = false;
  in_flight.save_directory.fill('\0');
  if (const char* save = std::getenv("COSIM_FUZZ_SAVE"); save && *save) {
    const fs::path directory = fs::absolute(fs::path(save) / target.name);
    fs::create_directories(directory);
    const std::string text = directory.string();
    std::memcpy(in_flight.save_directory.data(), text.data(),
                std::min(text.size(), in_flight.save_directory.size() - 1));
  }
  const std::uint64_t executions =
      environment_number("COSIM_FUZZ_EXECUTIONS", target.default_executions);
  const std::uint64_t seed = environment_number("COSIM_FUZZ_SEED", 23);

  std::vector<std::string> corpus = target.seeds;
  const std::vector<std::string> kept = regression_inputs(target.name);
  corpus.insert(corpus.end(), kept.begin(), kept.end());
  Mutator mutator(seed, target.tokens, corpus);

  const CrashReport crash_report;
  Watchdog watchdog(target.hang_limit);
  const auto start = std::chrono::steady_clock::now();
  constexpr std::size_t enough_failures = 20;
  for (const std::string& input : kept) {
    ++report.regression_inputs;
    if (auto failure = run_one(target, input, watchdog, report); !failure.empty())
      record(target, input, failure, report);
  }
  for (std::uint64_t i = 0; i < executions && report.failures.size() < enough_failures; ++i) {
    const std::string& original = corpus[mutator.below(corpus.size())];
    const std::string input = target.mutate ? target.mutate(original, mutator)
                                            : mutator.mutate(original, target.max_size);
    ++report.executions;
    if (auto failure = run_one(target, input, watchdog, report); !failure.empty())
      record(target, input, failure, report);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace cosim::testing
