#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "com/transport.hpp"

// The coupler's side of participants on several ranks, in the spirit of
// preCICE's m2n: each rank of such a participant is a connection of its own
// on the transport below. This hub zips what the ranks send, message by
// message, into one participant's messages (the fields assembled from the
// parts each rank declared), and splits what the coupler sends into the
// ranks' parts, so the coupling scheme sees one participant. A participant
// on one rank passes through untouched. (architecture.md §15)
namespace cosim::m2n {

class PartitionedHub final : public com::Hub {
 public:
  // `part_peer` names part k of n of a participant on the transport below
  // (what the launch line starts at that rank).
  using PartPeerName =
      std::function<std::string(const std::string& participant, int part, int parts)>;
  PartitionedHub(com::Hub& connections, PartPeerName part_peer);
  ~PartitionedHub() override;
  PartitionedHub(const PartitionedHub&) = delete;
  PartitionedHub& operator=(const PartitionedHub&) = delete;

  void admit(const std::string& connection, const std::string& participant) override;
  void send(const std::string& peer, const com::Message& message) override;
  std::optional<com::Received> receive(std::chrono::milliseconds timeout) override;
  std::string describe() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosim::m2n
