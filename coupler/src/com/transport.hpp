#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "com/message.hpp"

// A transport moves messages between the coupler (the hub) and the
// participants. Peers are named: the coupler addresses participants by their
// participant name, participants address the coupler as `coupler_peer`.
namespace cosim::com {

inline constexpr const char* coupler_peer = "coupler";

struct Received {
  // The participant's name, or for a hub's connection that has not been
  // admitted yet, the connection's label (e.g. "connection #3"), which never
  // equals a participant's name.
  std::string peer;
  bool admitted = true;
  Message message;
  // A hub's connection that has not been admitted sent frames that are not a
  // cosim message: why (and `message` is empty). Admitted peers' malformed
  // frames are a ProtocolError instead.
  std::optional<std::string> malformed;
};

class Transport {
 public:
  virtual ~Transport() = default;
  virtual void send(const std::string& peer, const Message& message) = 0;
  // Waits at most `timeout` for one message; nullopt when none came.
  virtual std::optional<Received> receive(std::chrono::milliseconds timeout) = 0;
  // A human-readable description of where this transport listens/connects.
  virtual std::string describe() const = 0;
};

// The coupler's side: many connections, each of which becomes a participant
// only once the coupler has checked its hello. Messages from connections not
// admitted come with `admitted == false`; frames from them that cannot be
// decoded come back as `malformed` (never as an exception), so a stranger
// cannot end a run by writing garbage to the endpoint.
class Hub : public Transport {
 public:
  // From now on messages from `connection` come from `participant`, and
  // send(participant) reaches that connection alone. Throws ProtocolError
  // when the transport knows the connection cannot be that participant.
  virtual void admit(const std::string& connection, const std::string& participant) = 0;
};

}  // namespace cosim::com
