// MPI transport figures, run as `mpirun -np 2 mpi_transport_bench`: rank 0
// is the hub and times round trips, rank 1 echoes.

#include <benchmark/benchmark.h>

#include <memory>

#include "com/mpi_transport.hpp"

namespace {

using namespace cosim;
using namespace std::chrono_literals;

std::unique_ptr<com::MpiHub> hub;

void round_trips(benchmark::State& state, std::size_t doubles) {
  const std::vector<double> values(doubles, 1.0);
  const com::Message m = com::make_field_message("bench", "coupler", 0, 0.0, "f", "m", values, 1);
  for (auto _ : state) {
    hub->send("echo", m);
    auto r = hub->receive(60s);
    benchmark::DoNotOptimize(r);
  }
  state.counters["bytes_per_s_one_way"] = benchmark::Counter(
      2.0 * static_cast<double>(doubles * sizeof(double)) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}

void BM_MpiRoundTripSmall(benchmark::State& s) {
  round_trips(s, 1);
}
void BM_MpiThroughput(benchmark::State& s) {
  round_trips(s, static_cast<std::size_t>(s.range(0)));
}
BENCHMARK(BM_MpiRoundTripSmall)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MpiThroughput)
    ->Arg(1'000'000)
    ->Arg(10'000'000)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  if (std::getenv("OMPI_COMM_WORLD_RANK") &&
      std::string(std::getenv("OMPI_COMM_WORLD_RANK")) != "0") {
    com::MpiClient client("echo");
    client.send(com::coupler_peer,
                com::make_text_message(com::MessageType::hello, "bench", "echo", 0, 0.0, "hi"));
    for (;;) {
      auto r = client.receive(600s);
      if (!r || r->message.header.type == com::MessageType::finish) break;
      client.send(com::coupler_peer, r->message);
    }
    return 0;
  }
  hub = std::make_unique<com::MpiHub>(std::vector<std::string>{"echo"});
  const auto hello = hub->receive(60s);  // the echo rank's hello
  hub->admit(hello->peer, "echo");
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  hub->send("echo",
            com::make_text_message(com::MessageType::finish, "bench", "coupler", 0, 0.0, ""));
  hub.reset();
  return 0;
}
