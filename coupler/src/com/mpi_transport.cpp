#include "com/mpi_transport.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <thread>

#include "com/allocator_tuning.hpp"
#include "cosim/error.hpp"

#ifdef COSIM_HAVE_MPI
#include <mpi.h>

#include "cosim/runtime/application_communicator.hpp"
#endif

namespace cosim::com {

#ifdef COSIM_HAVE_MPI

namespace {

constexpr int header_tag = 7001;
constexpr int payload_tag = 7002;
constexpr std::size_t max_chunk = std::size_t{1} << 30;
constexpr int coupler_rank = 0;

// MPI is initialised once per process and finalised when the last transport
// goes away.
class MpiEnvironment {
 public:
  static MpiEnvironment& instance() {
    static MpiEnvironment env;
    return env;
  }
  void acquire() {
    if (users_++ > 0) return;
    tune_allocator_for_large_fields();
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
      int provided = 0;
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
      owns_ = true;
    }
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    local_ = runtime::application_communicator();
    MPI_Comm_dup(MPI_COMM_WORLD, &coupling_);
  }
  void release() {
    if (--users_ > 0) return;
    MPI_Comm_free(&coupling_);
    if (owns_) {
      int finalized = 0;
      MPI_Finalized(&finalized);
      if (!finalized) MPI_Finalize();
    }
  }
  MPI_Comm coupling() const { return coupling_; }
  MPI_Comm local() const { return local_; }

 private:
  int users_ = 0;
  bool owns_ = false;
  MPI_Comm local_ = MPI_COMM_NULL;
  MPI_Comm coupling_ = MPI_COMM_NULL;
};

void check(int rc, const std::string& peer, const char* what) {
  if (rc == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int len = 0;
  MPI_Error_string(rc, text, &len);
  throw ProtocolError(peer, fmt::format("MPI {} failed: {}", what, std::string(text, len)));
}

void send_to(MPI_Comm comm, int rank, const std::string& peer, const Message& message) {
  const std::vector<std::byte> header = encode_header(message.header);
  check(MPI_Send(header.data(), static_cast<int>(header.size()), MPI_BYTE, rank, header_tag, comm),
        peer, "send of a header");
  auto bytes = message.payload.bytes();
  // Payloads go in chunks of at most 1 GiB, and always at least one message.
  std::size_t offset = 0;
  do {
    const std::size_t n = std::min(max_chunk, bytes.size() - offset);
    check(MPI_Send(bytes.data() + offset, static_cast<int>(n), MPI_BYTE, rank, payload_tag, comm),
          peer, "send of a payload");
    offset += n;
  } while (offset < bytes.size());
}

// Polls for a header from `source` (or any) until the timeout. The first
// millisecond yields the core between probes (an answer usually comes within
// it, and oversubscribed runs still make progress); after that the waiting
// process sleeps between probes so a long wait costs no CPU.
std::optional<int> probe_header(MPI_Comm comm, int source, std::chrono::milliseconds timeout) {
  const auto start = std::chrono::steady_clock::now();
  const auto deadline = start + timeout;
  const auto eager_until = start + std::chrono::milliseconds(1);
  for (;;) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(source, header_tag, comm, &flag, &status);
    if (flag) return status.MPI_SOURCE;
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) return std::nullopt;
    if (now < eager_until)
      std::this_thread::yield();
    else
      std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

Received receive_from(MPI_Comm comm, int source, const std::string& peer_hint) {
  MPI_Status status;
  MPI_Probe(source, header_tag, comm, &status);
  int size = 0;
  MPI_Get_count(&status, MPI_BYTE, &size);
  std::vector<std::byte> header(static_cast<std::size_t>(size));
  check(MPI_Recv(header.data(), size, MPI_BYTE, source, header_tag, comm, MPI_STATUS_IGNORE),
        peer_hint, "receive of a header");
  Received r;
  r.message.header = decode_header(header, peer_hint);
  r.peer = peer_hint;
  std::size_t total = 0;
  if (r.message.header.element == ElementType::float64)
    total = r.message.header.count * r.message.header.components * sizeof(double);
  else if (r.message.header.element == ElementType::text)
    total = r.message.header.count;
  auto storage = std::make_shared<std::vector<std::byte>>();
  std::size_t offset = 0;
  do {
    MPI_Probe(source, payload_tag, comm, &status);
    int n = 0;
    MPI_Get_count(&status, MPI_BYTE, &n);
    if (storage->size() < offset + static_cast<std::size_t>(n)) storage->resize(offset + n);
    check(MPI_Recv(storage->data() + offset, n, MPI_BYTE, source, payload_tag, comm,
                   MPI_STATUS_IGNORE),
          peer_hint, "receive of a payload");
    offset += static_cast<std::size_t>(n);
  } while (offset < total && offset % max_chunk == 0 && offset > 0);
  const auto* data = storage->data();
  r.message.payload = Payload::adopt(std::move(storage), data, offset);
  return r;
}

}  // namespace

struct MpiHub::Impl {
  std::vector<std::string> participants;  // by world rank - 1 (a part's peer name, e.g. "soil[1]")
  std::map<std::string, int> rank_of;     // admitted participants
  std::map<int, std::string> name_of;
  int world_size = 0;

  static std::string label(int rank) { return fmt::format("world rank {}", rank); }
};

MpiHub::MpiHub(std::vector<std::string> participants) : impl_(std::make_unique<Impl>()) {
  impl_->participants = std::move(participants);
  MpiEnvironment::instance().acquire();
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &impl_->world_size);
  if (rank != coupler_rank)
    throw InputError(
        fmt::format("cosim must be the first application of the mpirun line (world "
                    "rank 0), it is rank {}",
                    rank));
}

MpiHub::~MpiHub() {
  MpiEnvironment::instance().release();
}

int MpiHub::world_size() const {
  return impl_->world_size;
}

std::string MpiHub::describe() const {
  return fmt::format("MPI hub (world rank 0 of {})", impl_->world_size);
}

std::string MpiHub::participant_of_rank(int rank) const {
  if (rank < 1 || rank > static_cast<int>(impl_->participants.size())) return {};
  return impl_->participants[static_cast<std::size_t>(rank - 1)];
}

void MpiHub::abort_job(int exit_code) {
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::_Exit(exit_code);  // MPI_Abort does not return; in case it does
}

// The launch line says which participant (or which part of one) runs at each
// world rank: a rank is admitted as that one only.
void MpiHub::admit(const std::string& connection, const std::string& participant) {
  for (int rank = 1; rank < impl_->world_size; ++rank) {
    if (Impl::label(rank) != connection) continue;
    const std::string expected = participant_of_rank(rank);
    if (participant != expected)
      throw ProtocolError(connection, fmt::format("said hello as '{}', but the mpirun line starts "
                                                  "participant '{}' at this rank",
                                                  participant, expected));
    if (impl_->rank_of.count(participant))
      throw std::logic_error("admit: participant '" + participant + "' is already admitted");
    impl_->rank_of[participant] = rank;
    impl_->name_of[rank] = participant;
    return;
  }
  throw std::logic_error("admit: no connection '" + connection + "'");
}

void MpiHub::send(const std::string& peer, const Message& message) {
  auto it = impl_->rank_of.find(peer);
  if (it != impl_->rank_of.end()) {
    send_to(MpiEnvironment::instance().coupling(), it->second, peer, message);
    return;
  }
  for (int rank = 1; rank < impl_->world_size; ++rank)
    if (Impl::label(rank) == peer && !impl_->name_of.count(rank)) {
      send_to(MpiEnvironment::instance().coupling(), rank, peer, message);
      return;
    }
  throw ProtocolError(peer, "has not said hello (cannot send)");
}

std::optional<Received> MpiHub::receive(std::chrono::milliseconds timeout) {
  MPI_Comm comm = MpiEnvironment::instance().coupling();
  auto source = probe_header(comm, MPI_ANY_SOURCE, timeout);
  if (!source) return std::nullopt;
  auto known = impl_->name_of.find(*source);
  const bool admitted = known != impl_->name_of.end();
  const std::string peer = admitted ? known->second : Impl::label(*source);
  try {
    Received r = receive_from(comm, *source, peer);
    r.admitted = admitted;
    return r;
  } catch (const ProtocolError& e) {
    if (admitted) throw;
    Received r;
    r.peer = peer;
    r.admitted = false;
    r.malformed = e.what();
    return r;
  }
}

struct MpiClient::Impl {
  std::string name;
};

MpiClient::MpiClient(const std::string& participant_name) : impl_(std::make_unique<Impl>()) {
  impl_->name = participant_name;
  MpiEnvironment::instance().acquire();
}

MpiClient::~MpiClient() {
  MpiEnvironment::instance().release();
}

std::string MpiClient::describe() const {
  return "MPI client of world rank 0";
}

int MpiClient::application_rank() const {
  int rank = 0;
  MPI_Comm_rank(MpiEnvironment::instance().local(), &rank);
  return rank;
}

int MpiClient::application_size() const {
  int size = 1;
  MPI_Comm_size(MpiEnvironment::instance().local(), &size);
  return size;
}

void MpiClient::send(const std::string& peer, const Message& message) {
  if (peer != coupler_peer)
    throw std::logic_error("a participant sends only to the coupler, not to '" + peer + "'");
  send_to(MpiEnvironment::instance().coupling(), coupler_rank, peer, message);
  if (message.header.type == MessageType::hello) runtime::note_hello_sent();
}

std::optional<Received> MpiClient::receive(std::chrono::milliseconds timeout) {
  MPI_Comm comm = MpiEnvironment::instance().coupling();
  if (!probe_header(comm, coupler_rank, timeout)) return std::nullopt;
  return receive_from(comm, coupler_rank, coupler_peer);
}

#else  // COSIM_HAVE_MPI

namespace {
[[noreturn]] void no_mpi() {
  throw InputError("this build of cosim has no MPI transport (configure with -DCOSIM_WITH_MPI=ON)");
}
}  // namespace

struct MpiHub::Impl {};
MpiHub::MpiHub(std::vector<std::string>) {
  no_mpi();
}
MpiHub::~MpiHub() = default;
int MpiHub::world_size() const {
  return 0;
}
std::string MpiHub::participant_of_rank(int) const {
  return {};
}
void MpiHub::abort_job(int exit_code) {
  std::_Exit(exit_code);
}
void MpiHub::admit(const std::string&, const std::string&) {
  no_mpi();
}
void MpiHub::send(const std::string&, const Message&) {
  no_mpi();
}
std::optional<Received> MpiHub::receive(std::chrono::milliseconds) {
  no_mpi();
}
std::string MpiHub::describe() const {
  return "MPI (not built)";
}
struct MpiClient::Impl {};
MpiClient::MpiClient(const std::string&) {
  no_mpi();
}
MpiClient::~MpiClient() = default;
void MpiClient::send(const std::string&, const Message&) {
  no_mpi();
}
std::optional<Received> MpiClient::receive(std::chrono::milliseconds) {
  no_mpi();
}
std::string MpiClient::describe() const {
  return "MPI (not built)";
}
int MpiClient::application_rank() const {
  return 0;
}
int MpiClient::application_size() const {
  return 1;
}

#endif  // COSIM_HAVE_MPI

}  // namespace cosim::com
