// m2n::PartitionedHub over a scripted transport: the ranks of a participant
// say hello and are admitted together; their parts of a grid and of a cloud
// are assembled into the whole mesh's fields exactly (any order of
// elements), and what the coupler sends is split back; ranks out of step,
// parts that miss or repeat elements, and a rank's abort are reported.
#include "m2n/partitioned_hub.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <deque>
#include <map>

#include "com/handshake.hpp"
#include "cosim/error.hpp"

namespace cosim::m2n {
namespace {

using ::testing::HasSubstr;

// The transport below: messages queued by the test arrive in order; what
// the hub sends and admits is recorded.
class ScriptedHub final : public com::Hub {
 public:
  std::deque<com::Received> incoming;
  std::map<std::string, std::vector<com::Message>> sent;  // by the transport's peer
  std::map<std::string, std::string> admitted;            // connection -> peer

  void admit(const std::string& connection, const std::string& peer) override {
    admitted[connection] = peer;
  }
  void send(const std::string& peer, const com::Message& m) override { sent[peer].push_back(m); }
  std::optional<com::Received> receive(std::chrono::milliseconds) override {
    if (incoming.empty()) return std::nullopt;
    com::Received r = std::move(incoming.front());
    incoming.pop_front();
    return r;
  }
  std::string describe() const override { return "scripted"; }
};

std::string part_name(const std::string& p, int part, int parts) {
  return parts > 1 ? fmt::format("{}[{}]", p, part) : p;
}

com::Hello hello_of(int part, int parts) {
  com::Hello h;
  h.participant = "soil";
  h.config_hash = "abc";
  h.program = "test";
  h.pid = 100 + part;
  h.meshes = {{"grid", MeshKind::uniform_grid, 2}, {"points", MeshKind::point_cloud, 2}};
  h.part = part;
  h.parts = parts;
  h.partitioned = true;
  return h;
}

com::Message text(com::MessageType type, const std::string& body) {
  return com::make_text_message(type, "job", "soil", 0, 0.0, body);
}

com::Message doubles(com::MessageType type, const std::string& mesh, const std::string& field,
                     const std::vector<double>& v, std::uint32_t components = 1) {
  com::Message m = com::make_field_message("job", "soil", 0, 0.0, field, mesh, v, components);
  m.header.type = type;
  return m;
}

// A 3 x 2 cell grid: rank 0 holds cells 0, 2, 4, rank 1 cells 5, 3, 1 (in
// that order), and a cloud of 3 points, rank 0 the points 2 and 0, rank 1
// point 1.
struct TwoRanks : ::testing::Test {
  ScriptedHub below;
  PartitionedHub hub{below, part_name};
  UniformGrid grid{.dim = 2, .cells = {3, 2, 1}};
  std::vector<std::vector<double>> grid_parts{{0, 2, 4}, {5, 3, 1}};
  std::vector<std::vector<double>> cloud_parts{{2, 0}, {1}};

  void arrive(int rank, com::Message m, bool admitted = true) {
    below.incoming.push_back(
        {admitted ? fmt::format("soil[{}]", rank) : fmt::format("connection #{}", rank), admitted,
         std::move(m), std::nullopt});
  }

  com::Received next() {
    auto r = hub.receive(std::chrono::milliseconds(0));
    if (!r) throw std::runtime_error("nothing arrived");
    return *r;
  }

  void connect() {
    arrive(1, text(com::MessageType::hello, com::to_json(hello_of(1, 2))), false);
    EXPECT_FALSE(hub.receive(std::chrono::milliseconds(0)));  // waits for rank 0
    arrive(0, text(com::MessageType::hello, com::to_json(hello_of(0, 2))), false);
    const com::Received merged = next();
    EXPECT_FALSE(merged.admitted);
    EXPECT_EQ(com::parse_hello(merged.message.payload.text(), merged.peer).parts, 2);
    hub.admit(merged.peer, "soil");
    EXPECT_EQ(below.admitted.at("connection #0"), "soil[0]");
    EXPECT_EQ(below.admitted.at("connection #1"), "soil[1]");
  }

  void send_meshes() {
    const Mesh whole{"grid", grid};
    for (int rank : {0, 1}) {
      arrive(rank, doubles(com::MessageType::mesh_part, "grid", "", grid_parts[rank]));
      arrive(rank, com::make_mesh_message("job", "soil", 0, 0.0, whole));
    }
  }
};

TEST_F(TwoRanks, AssemblesAGridFieldFromItsPartsAndSplitsTheAnswer) {
  connect();
  send_meshes();
  const com::Received mesh = next();
  EXPECT_EQ(mesh.peer, "soil");
  EXPECT_EQ(com::decode_mesh_message(mesh.message, "soil").size(), 6u);
  // Each rank's values are 10 * element + component, two components.
  for (int rank : {0, 1}) {
    std::vector<double> v;
    for (double e : grid_parts[rank]) v.insert(v.end(), {10 * e, 10 * e + 1});
    arrive(rank, doubles(com::MessageType::field, "grid", "velocity", v, 2));
  }
  const com::Received field = next();
  ASSERT_EQ(field.message.header.count, 6u);
  const auto whole = field.message.payload.doubles();
  for (std::size_t e = 0; e < 6; ++e) {
    EXPECT_EQ(whole[2 * e], 10.0 * static_cast<double>(e));
    EXPECT_EQ(whole[2 * e + 1], 10.0 * static_cast<double>(e) + 1);
  }
  hub.send("soil", field.message);
  for (int rank : {0, 1}) {
    const auto& got = below.sent.at(fmt::format("soil[{}]", rank));
    ASSERT_EQ(got.size(), 1u);
    const auto mine = got[0].payload.doubles();
    ASSERT_EQ(got[0].header.count, 3u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(mine[2 * i], 10.0 * grid_parts[rank][i]);
  }
  // A message without a mesh goes to every rank.
  hub.send("soil", text(com::MessageType::finish, ""));
  EXPECT_EQ(below.sent.at("soil[0]").size(), 2u);
  EXPECT_EQ(below.sent.at("soil[1]").size(), 2u);
}

// Parts with ghosts: rank 0 holds cells 0-3 and owns 0-2, rank 1 holds 2-5
// and owns 3-5. The field is assembled from the owned values; every rank is
// sent the values of every cell it holds.
TEST_F(TwoRanks, TakesOwnedValuesAndSendsGhostsToo) {
  connect();
  const Mesh whole{"grid", grid};
  const std::vector<std::vector<double>> records{{0, 1, 1, 1, 2, 1, 3, 0},
                                                 {2, 0, 3, 1, 4, 1, 5, 1}};
  for (int rank : {0, 1}) {
    arrive(rank, doubles(com::MessageType::mesh_part, "grid", "", records[rank], 2));
    arrive(rank, com::make_mesh_message("job", "soil", 0, 0.0, whole));
  }
  next();
  arrive(0, doubles(com::MessageType::field, "grid", "p", {0, 10, 20}));
  arrive(1, doubles(com::MessageType::field, "grid", "p", {30, 40, 50}));
  const com::Received field = next();
  EXPECT_EQ(field.message.payload.doubles(), (std::vector<double>{0, 10, 20, 30, 40, 50}));
  hub.send("soil", field.message);
  EXPECT_EQ(below.sent.at("soil[0]").back().payload.doubles(),
            (std::vector<double>{0, 10, 20, 30}));
  EXPECT_EQ(below.sent.at("soil[1]").back().payload.doubles(),
            (std::vector<double>{20, 30, 40, 50}));
}

TEST_F(TwoRanks, AssemblesACloudFromItsRanksPoints) {
  connect();
  PointCloud mine0{2, {2.0, 2.5, 0.0, 0.5}, {0.2, 0.01}};  // points 2 and 0
  PointCloud mine1{2, {1.0, 1.5}, {0.1}};                  // point 1
  arrive(0, doubles(com::MessageType::mesh_part, "points", "", cloud_parts[0]));
  arrive(0, com::make_mesh_message("job", "soil", 0, 0.0, Mesh{"points", mine0}));
  arrive(1, doubles(com::MessageType::mesh_part, "points", "", cloud_parts[1]));
  arrive(1, com::make_mesh_message("job", "soil", 0, 0.0, Mesh{"points", mine1}));
  const Mesh cloud = com::decode_mesh_message(next().message, "soil");
  ASSERT_EQ(cloud.size(), 3u);
  for (std::size_t p = 0; p < 3; ++p) EXPECT_EQ(cloud.position(p)[0], static_cast<double>(p));
  EXPECT_EQ(cloud.control_volume(0), 0.01);
  EXPECT_EQ(cloud.control_volume(2), 0.2);
}

TEST_F(TwoRanks, RefusesPartsThatMissOrRepeatAnElement) {
  connect();
  grid_parts[1] = {5, 3, 0};  // element 0 twice, element 1 nobody's
  send_meshes();
  try {
    next();
    FAIL() << "accepted parts that repeat an element";
  } catch (const ProtocolError& e) {
    EXPECT_THAT(e.what(), HasSubstr("do not cover its 6 elements once each"));
  }
}

TEST_F(TwoRanks, RefusesRanksOutOfStep) {
  connect();
  send_meshes();
  next();
  arrive(0, doubles(com::MessageType::field, "grid", "velocity", {1, 2, 3}));
  arrive(1, text(com::MessageType::window_end, ""));
  try {
    next();
    FAIL() << "zipped different messages";
  } catch (const ProtocolError& e) {
    EXPECT_THAT(e.what(), HasSubstr("out of step"));
    EXPECT_THAT(e.what(), HasSubstr("window_end"));
  }
}

TEST_F(TwoRanks, OneRanksAbortIsTheParticipantsAtOnce) {
  connect();
  arrive(1, text(com::MessageType::abort, "rank 1 failed"));
  const com::Received r = next();
  EXPECT_EQ(r.peer, "soil");
  EXPECT_EQ(r.message.header.type, com::MessageType::abort);
  EXPECT_EQ(r.message.payload.text(), "rank 1 failed");
}

TEST_F(TwoRanks, RefusesRanksThatDeclareDifferentFields) {
  com::Hello other = hello_of(1, 2);
  FieldSpec extra;
  extra.name = "extra";
  extra.mesh = "grid";
  other.writes.push_back(extra);
  arrive(0, text(com::MessageType::hello, com::to_json(hello_of(0, 2))), false);
  arrive(1, text(com::MessageType::hello, com::to_json(other)), false);
  const com::Received r = next();
  ASSERT_TRUE(r.malformed);
  EXPECT_THAT(*r.malformed, HasSubstr("declare different meshes, fields or jobs"));
}

TEST(PartitionedHub, PassesAParticipantOnOneRankThrough) {
  ScriptedHub below;
  PartitionedHub hub(below, part_name);
  com::Hello h = hello_of(0, 1);
  below.incoming.push_back(
      {"connection #0", false, text(com::MessageType::hello, com::to_json(h)), std::nullopt});
  const auto r = hub.receive(std::chrono::milliseconds(0));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->peer, "connection #0");
  hub.admit(r->peer, "soil");
  EXPECT_EQ(below.admitted.at("connection #0"), "soil");
}

}  // namespace
}  // namespace cosim::m2n
