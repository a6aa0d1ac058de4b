#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "com/transport.hpp"

// ZeroMQ transports: the coupler binds one ROUTER socket, each participant
// connects a DEALER socket. The ROUTER assigns every connection its routing
// id; the coupler admits a connection under a participant's name once its
// hello checks out, so no client can take over another's name.
namespace cosim::com {

enum class ZmqScheme { ipc, tcp };

struct ZmqHubOptions {
  ZmqScheme scheme = ZmqScheme::ipc;
  // tcp only: the interface to bind. Anything but loopback needs
  // `allow_non_loopback` (the job's explicit config key).
  std::string tcp_host = "127.0.0.1";
  bool allow_non_loopback = false;
};

class ZmqHub final : public Hub {
 public:
  explicit ZmqHub(const ZmqHubOptions& options = {});
  ~ZmqHub() override;
  ZmqHub(const ZmqHub&) = delete;
  ZmqHub& operator=(const ZmqHub&) = delete;

  // The address participants connect to (ipc://<private dir>/coupler.sock or
  // tcp://127.0.0.1:<port>).
  const std::string& endpoint() const;
  // ipc only: the private directory (mode 0700) removed by the destructor;
  // those of earlier hubs whose process died are removed at construction.
  const std::filesystem::path& private_directory() const;

  void admit(const std::string& connection, const std::string& participant) override;
  void send(const std::string& peer, const Message& message) override;
  std::optional<Received> receive(std::chrono::milliseconds timeout) override;
  std::string describe() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class ZmqClient final : public Transport {
 public:
  ZmqClient(const std::string& endpoint, const std::string& participant_name);
  ~ZmqClient() override;
  ZmqClient(const ZmqClient&) = delete;
  ZmqClient& operator=(const ZmqClient&) = delete;

  // Messages go to the coupler; `peer` must be `coupler_peer`.
  void send(const std::string& peer, const Message& message) override;
  std::optional<Received> receive(std::chrono::milliseconds timeout) override;
  std::string describe() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosim::com
