// ZeroMQ transport figures: small-message round trip, field throughput, and
// the coupling overhead of one window with 1e6-value fields each way (two
// participants and the coupler in one process, over ipc, identity mapping).

#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "com/zmq_transport.hpp"
#include "cosim/error.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/participant.hpp"
#include "cplscheme/coupler.hpp"
#include "job/job.hpp"

namespace {

using namespace cosim;
using namespace std::chrono_literals;

com::ZmqHubOptions hub_options(bool tcp) {
  com::ZmqHubOptions o;
  o.scheme = tcp ? com::ZmqScheme::tcp : com::ZmqScheme::ipc;
  return o;
}

// The peer echoes every message back until told to finish.
void echo(com::Transport& client) {
  for (;;) {
    auto r = client.receive(10s);
    if (!r || r->message.header.type == com::MessageType::finish) return;
    client.send(com::coupler_peer, r->message);
  }
}

void round_trips(benchmark::State& state, bool tcp, std::size_t doubles) {
  com::ZmqHub hub(hub_options(tcp));
  com::ZmqClient client(hub.endpoint(), "echo");
  std::thread peer([&] { echo(client); });
  const std::vector<double> values(doubles, 1.0);
  const com::Message m = com::make_field_message("bench", "coupler", 0, 0.0, "f", "m", values, 1);
  // The first message tells the hub the peer exists; it is admitted as "echo".
  client.send(com::coupler_peer,
              com::make_text_message(com::MessageType::hello, "bench", "echo", 0, 0.0, "hi"));
  const auto hello = hub.receive(10s);
  hub.admit(hello->peer, "echo");
  for (auto _ : state) {
    hub.send("echo", m);
    auto r = hub.receive(10s);
    benchmark::DoNotOptimize(r);
  }
  hub.send("echo",
           com::make_text_message(com::MessageType::finish, "bench", "coupler", 0, 0.0, ""));
  peer.join();
  const double bytes = static_cast<double>(doubles * sizeof(double));
  state.counters["bytes_per_s_one_way"] = benchmark::Counter(
      2.0 * bytes * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_ZmqIpcRoundTripSmall(benchmark::State& s) {
  round_trips(s, false, 1);
}
void BM_ZmqTcpRoundTripSmall(benchmark::State& s) {
  round_trips(s, true, 1);
}
void BM_ZmqIpcThroughput(benchmark::State& s) {
  round_trips(s, false, static_cast<std::size_t>(s.range(0)));
}
void BM_ZmqTcpThroughput(benchmark::State& s) {
  round_trips(s, true, static_cast<std::size_t>(s.range(0)));
}

BENCHMARK(BM_ZmqIpcRoundTripSmall)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ZmqTcpRoundTripSmall)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ZmqIpcThroughput)
    ->Arg(1'000'000)
    ->Arg(10'000'000)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ZmqTcpThroughput)
    ->Arg(1'000'000)
    ->Arg(10'000'000)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// One coupling window with no computation: each participant writes a 1e6
// value field (100^3 grid), the coupler maps it onto the partner's identical
// grid and sends it on.
void BM_CouplingWindowOverhead1e6(benchmark::State& state) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "cosim_bench_window";
  fs::create_directories(dir);
  const double windows = 1e6;
  std::ofstream(dir / "job.yaml") << R"(kind: job
name: bench
end_time: 1.0e6
window: 1.0
window_timeout: 600
participants:
  a: {executable: none, meshes: {grid: {kind: uniform_grid, dim: 3}}, writes: {fa: grid}, reads: {fb: grid}}
  b: {executable: none, meshes: {grid: {kind: uniform_grid, dim: 3}}, writes: {fb: grid}, reads: {fa: grid}}
exchange:
  - {field: fa, from: a, to: b, mapping: consistent}
  - {field: fb, from: b, to: a, mapping: consistent}
)";
  const job::Job job = job::load_job(dir / "job.yaml");
  com::ZmqHub hub;
  RunSummary summary(dir, "bench");
  cplscheme::CouplerOptions options;
  options.output_dir = dir;
  options.job_id = "bench";
  cplscheme::Coupler coupler(job, hub, nullptr, summary, options);
  std::thread coupler_thread([&] {
    try {
      coupler.run();
    } catch (const std::exception&) {
    }
  });
  const Mesh grid{"grid", UniformGrid{3, {0, 0, 0}, {0.01, 0.01, 0.01}, {100, 100, 100}}};
  auto make = [&](const std::string& name, const std::string& out, const std::string& in) {
    auto p = std::make_unique<Participant>(
        name, CouplingEndpoint{hub.endpoint(), name, "bench", job.config_hash, 60.0, ""});
    p->declare_mesh(grid);
    p->declare_write(FieldSpec{out, "grid", 1, "1", Quantity::intensive, TimeTreatment::state});
    p->declare_read(FieldSpec{in, "grid", 1, "1", Quantity::intensive, TimeTreatment::state});
    return p;
  };
  auto a = make("a", "fa", "fb");
  auto b = make("b", "fb", "fa");
  std::vector<double> va(grid.size(), 1.0), vb(grid.size(), 2.0);
  std::thread init_b([&] {
    b->write("fb", vb);
    b->initialize(0.0, windows);
  });
  a->write("fa", va);
  a->initialize(0.0, windows);
  init_b.join();
  // b follows a window after window until the coupler aborts the run.
  std::thread run_b([&] {
    std::vector<double> in(grid.size());
    try {
      while (b->is_coupling_ongoing()) {
        b->write("fb", vb);
        b->advance(b->max_time_step());
        b->read("fa", in);
      }
    } catch (const cosim::Error&) {
    }
  });
  std::vector<double> in(grid.size());
  for (auto _ : state) {
    a->write("fa", va);
    a->advance(a->max_time_step());
    a->read("fb", in);
  }
  a->abort("benchmark over");
  coupler_thread.join();
  run_b.join();
  state.counters["values_each_way"] = static_cast<double>(grid.size());
}
BENCHMARK(BM_CouplingWindowOverhead1e6)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(30);

}  // namespace

BENCHMARK_MAIN();
