#include "m2n/partitioned_hub.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <deque>
#include <vector>

#include "com/handshake.hpp"
#include "cosim/error.hpp"

namespace cosim::m2n {

static_assert(std::endian::native == std::endian::little,
              "m2n copies the payloads' little-endian doubles as bytes");

using com::Message;
using com::MessageType;
using com::Received;
using Clock = std::chrono::steady_clock;

namespace {

// Where each part's values go in the whole mesh: the part's element indices.
using Parts = std::vector<std::vector<std::int64_t>>;

// Moves the values of `elements` between a part's array (in the part's
// order) and the whole mesh's, `c` values an element, in runs of
// consecutive elements: a block of a grid's part is a few long runs. The
// payload bytes are little-endian doubles (com::Payload), copied as bytes.
enum class Direction { part_to_whole, whole_to_part };
void copy_runs(const std::byte* from, std::byte* to, const std::vector<std::int64_t>& elements,
               std::size_t c, Direction direction) {
  const std::size_t bytes = c * sizeof(double);
  for (std::size_t i = 0; i < elements.size();) {
    std::size_t run = 1;
    while (i + run < elements.size() &&
           elements[i + run] == elements[i] + static_cast<std::int64_t>(run))
      ++run;
    const std::size_t in_whole = static_cast<std::size_t>(elements[i]) * bytes;
    if (direction == Direction::part_to_whole)
      std::memcpy(to + in_whole, from + i * bytes, run * bytes);
    else
      std::memcpy(to + i * bytes, from + in_whole, run * bytes);
    i += run;
  }
}

std::string describe_head(const Message& m) {
  std::string out = com::to_string(m.header.type);
  if (!m.header.field.empty()) out += fmt::format(" '{}'", m.header.field);
  if (!m.header.mesh.empty()) out += fmt::format(" on '{}'", m.header.mesh);
  return out + fmt::format(" of window {}", m.header.window);
}

// A hello's declarations without what differs between the ranks.
std::string declarations_of(com::Hello hello) {
  hello.part = 0;
  hello.pid = 0;
  return com::to_json(hello);
}

}  // namespace

// A participant on several ranks: its ranks' connections, and what they
// sent that is not merged yet.
struct Group {
  std::string name;
  int parts = 0;
  std::string label;                     // its connection's name until admitted
  std::vector<std::string> connections;  // by part: before admission, the transport's labels
  std::vector<std::optional<Received>> hellos;
  std::vector<std::string> peers;  // by part, once admitted
  std::vector<std::deque<Message>> queues;
  std::map<std::string, Parts> elements;         // mesh -> each part's owned elements
  std::map<std::string, Parts> held;             // mesh -> each part's elements, ghosts too
  std::map<std::string, std::size_t> mesh_size;  // mesh -> elements of the whole mesh
  bool aborted = false;

  std::size_t hellos_received() const {
    return static_cast<std::size_t>(
        std::count_if(hellos.begin(), hellos.end(), [](const auto& h) { return h.has_value(); }));
  }
};

struct PartitionedHub::Impl {
  com::Hub& connections;
  PartPeerName part_peer;
  std::map<std::string, Group> groups;                    // by participant name
  std::map<std::string, std::pair<Group*, int>> part_of;  // the transport's peer -> part
  std::map<std::string, Group*> pending;                  // a group's label -> the group
  std::deque<Received> ready;

  Impl(com::Hub& c, PartPeerName p) : connections(c), part_peer(std::move(p)) {}

  static Received refused(const Received& r, std::string why) {
    Received out;
    out.peer = r.peer;
    out.admitted = false;
    out.malformed = std::move(why);
    return out;
  }

  // A hello from a rank of a participant on several ranks waits for the
  // others; the last one completes the participant's hello.
  void collect_hello(const Received& r, const com::Hello& hello) {
    Group& g = groups[hello.participant];
    if (g.parts == 0) {
      g.name = hello.participant;
      g.parts = hello.parts;
      g.label = fmt::format("the {} ranks of '{}'", hello.parts, hello.participant);
      g.connections.resize(static_cast<std::size_t>(g.parts));
      g.hellos.resize(static_cast<std::size_t>(g.parts));
    }
    const auto k = static_cast<std::size_t>(hello.part);
    if (!g.peers.empty() || g.parts != hello.parts || g.hellos[k]) {
      ready.push_back(
          refused(r, fmt::format("said hello as part {} of {} of '{}', which {}", hello.part,
                                 hello.parts, hello.participant,
                                 !g.peers.empty() ? "is connected already"
                                 : g.parts != hello.parts
                                     ? fmt::format("another rank said has {} parts", g.parts)
                                     : "another rank said hello as already")));
      return;
    }
    g.hellos[k] = r;
    g.connections[k] = r.peer;
    if (g.hellos_received() < static_cast<std::size_t>(g.parts)) return;

    const std::string declared =
        declarations_of(com::parse_hello(g.hellos[0]->message.payload.text(), r.peer));
    for (int p = 1; p < g.parts; ++p) {
      const auto& h = *g.hellos[static_cast<std::size_t>(p)];
      if (declarations_of(com::parse_hello(h.message.payload.text(), h.peer)) != declared ||
          h.message.header.job_id != g.hellos[0]->message.header.job_id) {
        ready.push_back(refused(r, fmt::format("the ranks of '{}' declare different meshes, fields "
                                               "or jobs (part 0 and part {})",
                                               g.name, p)));
        return;
      }
    }
    Received merged = *g.hellos[0];
    merged.peer = g.label;
    pending[g.label] = &g;
    ready.push_back(std::move(merged));
  }

  // The whole mesh's geometry from its parts: a grid's (every rank sends it
  // whole), a cloud's elements each put where its part says.
  Message merge_mesh(Group& g, std::vector<Message>& heads) {
    const std::string& mesh = heads[0].header.mesh;
    auto found = g.elements.find(mesh);
    if (found == g.elements.end())
      throw ProtocolError(g.name, fmt::format("sent mesh '{}' without its parts", mesh));
    const Parts& parts = found->second;
    const bool grid = heads[0].header.field == to_string(MeshKind::uniform_grid);
    std::size_t whole = 0;
    if (grid) {
      const auto first = heads[0].payload.bytes();
      for (const auto& h : heads)
        if (!std::equal(first.begin(), first.end(), h.payload.bytes().begin(),
                        h.payload.bytes().end()))
          throw ProtocolError(g.name, fmt::format("its ranks sent different grids '{}'", mesh));
      whole = com::decode_mesh_message(heads[0], g.name).size();
    } else {
      for (std::size_t p = 0; p < heads.size(); ++p) {
        com::validate_payload(heads[p], g.name, false);
        if (heads[p].header.count != parts[p].size())
          throw ProtocolError(g.name, fmt::format("rank {} sent {} elements of mesh '{}', its part "
                                                  "names {}",
                                                  p, heads[p].header.count, mesh, parts[p].size()));
        whole += parts[p].size();
      }
    }
    std::vector<int> seen(whole, 0);
    for (std::size_t p = 0; p < parts.size(); ++p)
      for (const std::int64_t e : parts[p]) {
        if (e < 0 || static_cast<std::size_t>(e) >= whole || seen[static_cast<std::size_t>(e)]++)
          throw ProtocolError(g.name, fmt::format("the parts of mesh '{}' do not cover its {} "
                                                  "elements once each (rank {}, element {})",
                                                  mesh, whole, p, e));
      }
    if (std::find(seen.begin(), seen.end(), 0) != seen.end())
      throw ProtocolError(g.name, fmt::format("the parts of mesh '{}' leave some of its {} "
                                              "elements to no rank",
                                              mesh, whole));
    g.mesh_size[mesh] = whole;
    if (grid) return heads[0];
    return assemble(heads, parts, whole);
  }

  // Each part's records put at its elements' places in the whole.
  static Message assemble(const std::vector<Message>& heads, const Parts& parts,
                          std::size_t whole) {
    const std::size_t c = heads[0].header.components;
    auto values = std::make_shared<std::vector<double>>(whole * c);
    auto* to = reinterpret_cast<std::byte*>(values->data());
    for (std::size_t p = 0; p < heads.size(); ++p)
      copy_runs(heads[p].payload.bytes().data(), to, parts[p], c, Direction::part_to_whole);
    Message out;
    out.header = heads[0].header;
    out.header.count = whole;
    out.payload = com::Payload::share_doubles(std::move(values));
    return out;
  }

  // A mesh_part names, in the rank's order, the element of each value it
  // holds; with two components, also whether the rank owns it (a ghost's
  // value is sent to it but never taken from it).
  void store_parts(Group& g, const std::vector<Message>& heads) {
    Parts owned(heads.size()), held(heads.size());
    for (std::size_t p = 0; p < heads.size(); ++p) {
      com::validate_payload(heads[p], g.name, false);
      const std::size_t c = heads[p].header.components;
      if (c != 1 && c != 2)
        throw ProtocolError(g.name, fmt::format("rank {} sent the part of mesh '{}' with {} values "
                                                "an element",
                                                p, heads[p].header.mesh, c));
      const std::vector<double> v = heads[p].payload.doubles();
      for (std::size_t i = 0; i < v.size(); i += c) {
        const double e = v[i];
        if (!(e >= 0.0) || e != std::floor(e) || e > 0x1p52)
          throw ProtocolError(g.name, fmt::format("rank {} named element {} of mesh '{}'", p, e,
                                                  heads[p].header.mesh));
        held[p].push_back(static_cast<std::int64_t>(e));
        if (c == 1 || v[i + 1] != 0.0) owned[p].push_back(static_cast<std::int64_t>(e));
      }
    }
    g.elements[heads[0].header.mesh] = std::move(owned);
    g.held[heads[0].header.mesh] = std::move(held);
  }

  Message merge_field(Group& g, const std::vector<Message>& heads) {
    const std::string& mesh = heads[0].header.mesh;
    auto size = g.mesh_size.find(mesh);
    if (size == g.mesh_size.end())
      throw ProtocolError(g.name, fmt::format("sent field '{}' on mesh '{}' before the mesh",
                                              heads[0].header.field, mesh));
    const Parts& parts = g.elements.at(mesh);
    for (std::size_t p = 0; p < heads.size(); ++p) {
      com::validate_payload(heads[p], g.name, true);
      if (heads[p].header.count != parts[p].size() ||
          heads[p].header.components != heads[0].header.components)
        throw ProtocolError(g.name, fmt::format("rank {} sent field '{}' as {} x {}, its part of "
                                                "mesh '{}' has {} elements",
                                                p, heads[p].header.field, heads[p].header.count,
                                                heads[p].header.components, mesh, parts[p].size()));
    }
    return assemble(heads, parts, size->second);
  }

  // The heads of every rank's queue are the same message of the
  // participant: merged, or (a mesh's parts) kept here.
  std::optional<Message> merge(Group& g, std::vector<Message>& heads) {
    for (std::size_t p = 1; p < heads.size(); ++p) {
      const auto& a = heads[0].header;
      const auto& b = heads[p].header;
      if (a.type != b.type || a.window != b.window || a.field != b.field || a.mesh != b.mesh)
        throw ProtocolError(g.name,
                            fmt::format("its ranks are out of step: rank 0 sent {}, "
                                        "rank {} sent {}",
                                        describe_head(heads[0]), p, describe_head(heads[p])));
    }
    switch (heads[0].header.type) {
      case MessageType::mesh_part:
        store_parts(g, heads);
        return std::nullopt;
      case MessageType::mesh:
        return merge_mesh(g, heads);
      case MessageType::field:
        return merge_field(g, heads);
      default:
        return heads[0];
    }
  }

  void take(Group& g, int part, Message m) {
    if (g.aborted) return;
    if (m.header.type == MessageType::abort) {
      // One rank failing fails the participant, now.
      g.aborted = true;
      ready.push_back(Received{g.name, true, std::move(m), std::nullopt});
      return;
    }
    g.queues[static_cast<std::size_t>(part)].push_back(std::move(m));
    while (
        std::all_of(g.queues.begin(), g.queues.end(), [](const auto& q) { return !q.empty(); })) {
      std::vector<Message> heads;
      for (auto& q : g.queues) {
        heads.push_back(std::move(q.front()));
        q.pop_front();
      }
      if (auto merged = merge(g, heads))
        ready.push_back(Received{g.name, true, std::move(*merged), std::nullopt});
    }
  }

  void handle(Received r) {
    if (r.admitted) {
      auto part = part_of.find(r.peer);
      if (part == part_of.end()) {
        ready.push_back(std::move(r));
        return;
      }
      take(*part->second.first, part->second.second, std::move(r.message));
      return;
    }
    if (!r.malformed && r.message.header.type == MessageType::hello) {
      try {
        const com::Hello hello = com::parse_hello(r.message.payload.text(), r.peer);
        if (hello.parts > 1 && hello.partitioned) {
          collect_hello(r, hello);
          return;
        }
      } catch (const ProtocolError&) {
        // the coupling scheme refuses it with the reason
      }
    }
    ready.push_back(std::move(r));
  }

  // Part p's values of a field on the whole mesh.
  static Message part_of_field(const Message& whole, const std::vector<std::int64_t>& elements) {
    const std::size_t c = whole.header.components;
    auto values = std::make_shared<std::vector<double>>(elements.size() * c);
    copy_runs(whole.payload.bytes().data(), reinterpret_cast<std::byte*>(values->data()), elements,
              c, Direction::whole_to_part);
    Message out;
    out.header = whole.header;
    out.header.count = elements.size();
    out.payload = com::Payload::share_doubles(std::move(values));
    return out;
  }
};

PartitionedHub::PartitionedHub(com::Hub& connections, PartPeerName part_peer)
    : impl_(std::make_unique<Impl>(connections, std::move(part_peer))) {}

PartitionedHub::~PartitionedHub() = default;

void PartitionedHub::admit(const std::string& connection, const std::string& participant) {
  auto pending = impl_->pending.find(connection);
  if (pending == impl_->pending.end()) {
    impl_->connections.admit(connection, participant);
    return;
  }
  Group& g = *pending->second;
  if (g.name != participant)
    throw ProtocolError(connection, fmt::format("cannot be admitted as '{}'", participant));
  for (int p = 0; p < g.parts; ++p) {
    const std::string peer = impl_->part_peer(g.name, p, g.parts);
    impl_->connections.admit(g.connections[static_cast<std::size_t>(p)], peer);
    g.peers.push_back(peer);
    impl_->part_of[peer] = {&g, p};
  }
  g.queues.resize(static_cast<std::size_t>(g.parts));
  g.hellos.clear();
  impl_->pending.erase(pending);
}

void PartitionedHub::send(const std::string& peer, const Message& message) {
  if (auto pending = impl_->pending.find(peer); pending != impl_->pending.end()) {
    for (const auto& connection : pending->second->connections)
      impl_->connections.send(connection, message);
    return;
  }
  auto group = impl_->groups.find(peer);
  if (group == impl_->groups.end() || group->second.peers.empty()) {
    impl_->connections.send(peer, message);
    return;
  }
  const Group& g = group->second;
  auto parts = g.held.find(message.header.mesh);
  if (message.header.type != MessageType::field || parts == g.held.end()) {
    for (const auto& part : g.peers) impl_->connections.send(part, message);
    return;
  }
  if (message.header.count != g.mesh_size.at(message.header.mesh))
    throw std::logic_error(fmt::format("field '{}' for '{}' has {} elements, its mesh {}",
                                       message.header.field, g.name, message.header.count,
                                       g.mesh_size.at(message.header.mesh)));
  for (std::size_t p = 0; p < g.peers.size(); ++p)
    impl_->connections.send(g.peers[p], Impl::part_of_field(message, parts->second[p]));
}

std::optional<Received> PartitionedHub::receive(std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (impl_->ready.empty()) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    auto r = impl_->connections.receive(std::max(left, std::chrono::milliseconds(0)));
    if (!r) return std::nullopt;
    impl_->handle(std::move(*r));
  }
  Received r = std::move(impl_->ready.front());
  impl_->ready.pop_front();
  return r;
}

std::string PartitionedHub::describe() const {
  return impl_->connections.describe();
}

}  // namespace cosim::m2n
