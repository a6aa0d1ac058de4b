#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "cosim/com/message.hpp"

// A transport moves messages between the coupler (the hub) and the
// participants. Peers are named: the coupler addresses participants by their
// participant name, participants address the coupler as `coupler_peer`.
namespace cosim::com {

inline constexpr const char* coupler_peer = "coupler";

struct Received {
  std::string peer;
  Message message;
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

}  // namespace cosim::com
