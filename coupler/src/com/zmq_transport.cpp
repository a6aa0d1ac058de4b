#include "com/zmq_transport.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <array>
#include <cstdlib>
#include <map>
#include <set>
#include <system_error>
#include <zmq.hpp>

#include "com/allocator_tuning.hpp"
#include "cosim/error.hpp"
#include "private_directory.hpp"

namespace cosim::com {

namespace {

constexpr int linger_ms = 5000;  // let queued messages leave before a socket closes

zmq::message_t to_zmq(const Payload& payload) {
  if (payload.size() == 0) return zmq::message_t();
  // Zero copy: the zmq message keeps the payload's owner alive until sent.
  auto* keep_alive = new std::shared_ptr<const void>(payload.owner());
  return zmq::message_t(
      const_cast<std::byte*>(payload.bytes().data()), payload.size(),
      [](void*, void* hint) { delete static_cast<std::shared_ptr<const void>*>(hint); },
      keep_alive);
}

Payload from_zmq(zmq::message_t&& part) {
  auto owner = std::make_shared<zmq::message_t>(std::move(part));
  const auto* data = static_cast<const std::byte*>(owner->data());
  const std::size_t size = owner->size();
  return Payload::adopt(std::move(owner), data, size);
}

void send_parts(zmq::socket_t& socket, const std::string* routing_id, const Message& message) {
  const std::vector<std::byte> header = encode_header(message.header);
  if (routing_id) socket.send(zmq::buffer(*routing_id), zmq::send_flags::sndmore);
  socket.send(zmq::buffer(header.data(), header.size()), zmq::send_flags::sndmore);
  socket.send(to_zmq(message.payload), zmq::send_flags::none);
}

// Waits for the socket to be readable; a signal arriving meanwhile (EINTR)
// counts as nothing received, so the caller can look at why it was woken.
bool wait_readable(zmq::socket_t& socket, std::chrono::milliseconds timeout) {
  std::array<zmq::pollitem_t, 1> items{{{socket.handle(), 0, ZMQ_POLLIN, 0}}};
  try {
    return zmq::poll(items.data(), items.size(), timeout) > 0;
  } catch (const zmq::error_t& e) {
    if (e.num() == EINTR) return false;
    throw;
  }
}

// Reads the remaining parts of a multipart message; returns false (and drains)
// when the shape is not [header][payload].
bool receive_header_and_payload(zmq::socket_t& socket, zmq::message_t& header,
                                zmq::message_t& payload) {
  std::array<zmq::message_t*, 2> parts{&header, &payload};
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (!socket.get(zmq::sockopt::rcvmore)) return false;
    (void)socket.recv(*parts[i], zmq::recv_flags::none);
  }
  if (socket.get(zmq::sockopt::rcvmore)) {
    zmq::message_t extra;
    while (socket.get(zmq::sockopt::rcvmore)) (void)socket.recv(extra, zmq::recv_flags::none);
    return false;
  }
  return true;
}

// The address to bind for `host`: ZeroMQ takes an interface's IP address
// (IPv6 in brackets), not a host name.
std::string tcp_bind_address(const std::string& host) {
  if (host == "localhost") return "127.0.0.1";
  if (host.find(':') != std::string::npos && host.front() != '[') return "[" + host + "]";
  return host;
}

bool is_loopback(const std::string& host) {
  return host == "127.0.0.1" || host == "localhost" || host == "::1" || host == "[::1]" ||
         host.rfind("127.", 0) == 0;
}

}  // namespace

// The allocator is tuned before the context starts its I/O thread.
zmq::context_t make_context() {
  tune_allocator_for_large_fields();
  return zmq::context_t(1);
}

struct ZmqHub::Impl {
  zmq::context_t context = make_context();
  zmq::socket_t socket{context, zmq::socket_type::router};
  std::optional<PrivateDirectory> directory;
  std::string endpoint;
  // Connections by their ZeroMQ routing id (assigned by this socket: a
  // client cannot choose it, so it cannot pose as another).
  std::map<std::string, std::string> label_of;    // routing id -> label or participant
  std::map<std::string, std::string> routing_of;  // label or participant -> routing id
  std::set<std::string> admitted;
  std::size_t connections = 0;

  const std::string& label(const std::string& routing_id) {
    auto it = label_of.find(routing_id);
    if (it != label_of.end()) return it->second;
    const std::string l = fmt::format("connection #{}", ++connections);
    routing_of[l] = routing_id;
    return label_of[routing_id] = l;
  }
};

ZmqHub::ZmqHub(const ZmqHubOptions& options) : impl_(std::make_unique<Impl>()) {
  auto& s = impl_->socket;
  s.set(zmq::sockopt::router_mandatory, 1);
  s.set(zmq::sockopt::linger, linger_ms);
  s.set(zmq::sockopt::sndhwm, 0);
  s.set(zmq::sockopt::rcvhwm, 0);
  if (options.scheme == ZmqScheme::ipc) {
    impl_->directory.emplace(PrivateDirectory::create("cosim"));
    impl_->endpoint = "ipc://" + (impl_->directory->path() / "coupler.sock").string();
    s.bind(impl_->endpoint);
  } else {
    if (!is_loopback(options.tcp_host) && !options.allow_non_loopback)
      throw InputError(
          fmt::format("transport: binding tcp on '{}' (not loopback) needs "
                      "'zmq.allow_non_loopback: true' in the job",
                      options.tcp_host));
    const std::string address = tcp_bind_address(options.tcp_host);
    if (address.front() == '[') s.set(zmq::sockopt::ipv6, 1);
    try {
      s.bind(fmt::format("tcp://{}:*", address));
    } catch (const zmq::error_t& e) {
      throw InputError(
          fmt::format("zmq.host: cannot bind tcp on '{}': {} (give the IP address of "
                      "a local interface, e.g. 127.0.0.1 or ::1)",
                      options.tcp_host, e.what()));
    }
    impl_->endpoint = s.get(zmq::sockopt::last_endpoint);
  }
}

ZmqHub::~ZmqHub() {
  impl_->socket.close();
  impl_->context.close();
}

const std::string& ZmqHub::endpoint() const {
  return impl_->endpoint;
}
const std::filesystem::path& ZmqHub::private_directory() const {
  static const std::filesystem::path none;
  return impl_->directory ? impl_->directory->path() : none;
}
std::string ZmqHub::describe() const {
  return "zeromq hub at " + impl_->endpoint;
}

void ZmqHub::admit(const std::string& connection, const std::string& participant) {
  Impl& s = *impl_;
  auto it = s.routing_of.find(connection);
  if (it == s.routing_of.end() || s.admitted.count(connection))
    throw std::logic_error("admit: no connection '" + connection + "' awaiting admission");
  if (s.routing_of.count(participant))
    throw std::logic_error("admit: participant '" + participant + "' is already admitted");
  const std::string routing_id = it->second;
  s.routing_of.erase(it);
  s.routing_of[participant] = routing_id;
  s.label_of[routing_id] = participant;
  s.admitted.insert(participant);
}

void ZmqHub::send(const std::string& peer, const Message& message) {
  auto it = impl_->routing_of.find(peer);
  if (it == impl_->routing_of.end())
    throw ProtocolError(peer, "is not connected (cannot send to it)");
  try {
    send_parts(impl_->socket, &it->second, message);
  } catch (const zmq::error_t& e) {
    if (e.num() == EHOSTUNREACH) throw ProtocolError(peer, "is not connected (cannot send to it)");
    throw;
  }
}

std::optional<Received> ZmqHub::receive(std::chrono::milliseconds timeout) {
  Impl& s = *impl_;
  if (!wait_readable(s.socket, timeout)) return std::nullopt;
  zmq::message_t identity, header, payload;
  (void)s.socket.recv(identity, zmq::recv_flags::none);
  Received r;
  r.peer = s.label(identity.to_string());
  r.admitted = s.admitted.count(r.peer) > 0;
  try {
    if (!receive_header_and_payload(s.socket, header, payload))
      throw ProtocolError(r.peer, "sent a message that is not [header][payload]");
    r.message.header = decode_header(
        std::span(static_cast<const std::byte*>(header.data()), header.size()), r.peer);
  } catch (const ProtocolError& e) {
    if (r.admitted) throw;
    r.malformed = e.what();
    return r;
  }
  r.message.payload = from_zmq(std::move(payload));
  return r;
}

struct ZmqClient::Impl {
  zmq::context_t context = make_context();
  zmq::socket_t socket{context, zmq::socket_type::dealer};
  std::string endpoint;
  std::string name;
};

ZmqClient::ZmqClient(const std::string& endpoint, const std::string& participant_name)
    : impl_(std::make_unique<Impl>()) {
  if (endpoint.rfind("ipc://", 0) != 0 && endpoint.rfind("tcp://", 0) != 0)
    throw InputError(
        fmt::format("coupling endpoint '{}' is not an ipc:// or tcp:// address", endpoint));
  impl_->endpoint = endpoint;
  impl_->name = participant_name;
  // The hub assigns the routing id: a participant proves who it is by its
  // hello (name and run token), never by choosing an identity.
  auto& s = impl_->socket;
  s.set(zmq::sockopt::linger, linger_ms);
  s.set(zmq::sockopt::sndhwm, 0);
  s.set(zmq::sockopt::rcvhwm, 0);
  if (endpoint.find("://[") != std::string::npos) s.set(zmq::sockopt::ipv6, 1);
  s.connect(endpoint);
}

ZmqClient::~ZmqClient() {
  impl_->socket.close();
  impl_->context.close();
}

std::string ZmqClient::describe() const {
  return fmt::format("zeromq client '{}' of {}", impl_->name, impl_->endpoint);
}

void ZmqClient::send(const std::string& peer, const Message& message) {
  if (peer != coupler_peer)
    throw std::logic_error("a participant sends only to the coupler, not to '" + peer + "'");
  send_parts(impl_->socket, nullptr, message);
}

std::optional<Received> ZmqClient::receive(std::chrono::milliseconds timeout) {
  auto& s = impl_->socket;
  if (!wait_readable(s, timeout)) return std::nullopt;
  zmq::message_t header, payload;
  (void)s.recv(header, zmq::recv_flags::none);
  if (!s.get(zmq::sockopt::rcvmore))
    throw ProtocolError(coupler_peer, "sent a message without a payload part");
  (void)s.recv(payload, zmq::recv_flags::none);
  while (s.get(zmq::sockopt::rcvmore)) {
    zmq::message_t extra;
    (void)s.recv(extra, zmq::recv_flags::none);
  }
  Received r;
  r.peer = coupler_peer;
  r.message.header =
      decode_header(std::span(static_cast<const std::byte*>(header.data()), header.size()), r.peer);
  r.message.payload = from_zmq(std::move(payload));
  return r;
}

}  // namespace cosim::com
