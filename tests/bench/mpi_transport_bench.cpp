// MPI transport figures, run as `mpirun -np N mpi_transport_bench`: rank 0
// is the hub and times round trips; the other ranks are one echoing
// participant. With N = 2 it is a participant on one rank (the serial
// hub); with N > 2 a participant on N - 1 ranks, each holding an equal part
// of the field's mesh, behind m2n::PartitionedHub, which splits what the hub
// sends and assembles what the ranks send back: the cost of partitioned
// participants against the serial hub's, in one run of each.

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <mpi.h>

#include <memory>

#include "com/handshake.hpp"
#include "com/mpi_transport.hpp"
#include "m2n/partitioned_hub.hpp"

namespace {

using namespace cosim;
using namespace std::chrono_literals;

constexpr std::int64_t mesh_values = 1'000'000;  // a window's field, one value per cell

std::unique_ptr<com::MpiHub> connections;
std::unique_ptr<m2n::PartitionedHub> hub;

std::string part_name(const std::string& p, int part, int parts) {
  return parts > 1 ? fmt::format("{}[{}]", p, part) : p;
}

// A 1D grid of mesh_values cells.
Mesh grid() {
  UniformGrid g;
  g.cells = {mesh_values, 1, 1};
  return Mesh{"m", g};
}

// A field of the whole mesh there and back: split into the ranks' parts and
// assembled again when the participant is partitioned.
void window_round_trips(benchmark::State& state) {
  const std::vector<double> values(static_cast<std::size_t>(mesh_values), 1.0);
  const com::Message m = com::make_field_message("bench", "coupler", 0, 0.0, "f", "m", values, 1);
  for (auto _ : state) {
    hub->send("echo", m);
    auto r = hub->receive(60s);
    benchmark::DoNotOptimize(r);
  }
  state.counters["bytes_per_s_one_way"] = benchmark::Counter(
      2.0 * static_cast<double>(mesh_values * 8) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}

void small_round_trips(benchmark::State& state) {
  const com::Message m =
      com::make_text_message(com::MessageType::window_begin, "bench", "coupler", 0, 0.0, "");
  for (auto _ : state) {
    hub->send("echo", m);
    auto r = hub->receive(60s);
    benchmark::DoNotOptimize(r);
  }
}

void BM_MpiRoundTripSmall(benchmark::State& s) {
  small_round_trips(s);
}
void BM_MpiWindow1M(benchmark::State& s) {
  window_round_trips(s);
}
BENCHMARK(BM_MpiRoundTripSmall)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MpiWindow1M)->UseRealTime()->Unit(benchmark::kMillisecond);

// An echoing rank: part `part` of `parts` of the participant "echo".
int echo(int part, int parts) {
  com::MpiClient client("echo");
  com::Hello hello;
  hello.participant = "echo";
  hello.program = "mpi_transport_bench";
  hello.part = part;
  hello.parts = parts;
  hello.partitioned = parts > 1;
  client.send(com::coupler_peer, com::make_text_message(com::MessageType::hello, "bench", "echo", 0,
                                                        0.0, com::to_json(hello)));
  if (parts > 1) {
    std::vector<double> mine;
    for (std::int64_t e = mesh_values * part / parts; e < mesh_values * (part + 1) / parts; ++e)
      mine.push_back(static_cast<double>(e));
    com::Message ids = com::make_field_message("bench", "echo", 0, 0.0, "", "m", mine, 1);
    ids.header.type = com::MessageType::mesh_part;
    client.send(com::coupler_peer, ids);
    client.send(com::coupler_peer, com::make_mesh_message("bench", "echo", 0, 0.0, grid()));
  }
  for (;;) {
    auto r = client.receive(600s);
    if (!r || r->message.header.type == com::MessageType::finish) break;
    r->message.header.sender = "echo";
    client.send(com::coupler_peer, r->message);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int parts = size - 1;
  if (rank > 0) {
    echo(rank - 1, parts);
    MPI_Finalize();
    return 0;
  }
  std::vector<std::string> names;
  for (int p = 0; p < parts; ++p) names.push_back(part_name("echo", p, parts));
  connections = std::make_unique<com::MpiHub>(names);
  hub = std::make_unique<m2n::PartitionedHub>(*connections, part_name);
  const auto hello = hub->receive(60s);
  hub->admit(hello->peer, "echo");
  if (parts > 1) hub->receive(60s);  // the mesh
  std::printf("participant 'echo' on %d rank%s%s\n", parts, parts > 1 ? "s" : "",
              parts > 1 ? " (m2n::PartitionedHub splits and assembles)" : " (the serial hub)");
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  hub->send("echo",
            com::make_text_message(com::MessageType::finish, "bench", "coupler", 0, 0.0, ""));
  hub.reset();
  connections.reset();
  MPI_Finalize();
  return 0;
}
