#include "com/zmq_transport.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "cosim/error.hpp"

namespace cosim::com {
namespace {

using namespace std::chrono_literals;

void round_trip(ZmqHub& hub) {
  ZmqClient client(hub.endpoint(), "water");
  std::vector<double> values(1000);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.5 * static_cast<double>(i);
  client.send(coupler_peer, make_field_message("j", "water", 3, 0.25, "p", "grid", values, 1));
  auto r = hub.receive(5s);
  ASSERT_TRUE(r);
  // Not a participant until the hub admits the connection under a name.
  EXPECT_FALSE(r->admitted);
  EXPECT_NE(r->peer, "water");
  hub.admit(r->peer, "water");
  client.send(coupler_peer, make_field_message("j", "water", 3, 0.25, "p", "grid", values, 1));
  r = hub.receive(5s);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->admitted);
  EXPECT_EQ(r->peer, "water");
  EXPECT_EQ(r->message.header.window, 3u);
  EXPECT_EQ(r->message.payload.doubles(), values);
  hub.send("water", make_text_message(MessageType::finish, "j", coupler_peer, 4, 0.5, "bye"));
  auto back = client.receive(5s);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->message.header.type, MessageType::finish);
  EXPECT_EQ(back->message.payload.text(), "bye");
}

TEST(ZmqTransport, IpcEndpointLivesInAPrivateDirectoryRemovedAtTheEnd) {
  std::filesystem::path dir;
  {
    ZmqHub hub;
    dir = hub.private_directory();
    EXPECT_EQ(hub.endpoint().rfind("ipc://", 0), 0u);
    struct stat st {};
    ASSERT_EQ(::stat(dir.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0700);
    round_trip(hub);
  }
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(ZmqTransport, TcpBindsLoopbackOnly) {
  ZmqHubOptions o;
  o.scheme = ZmqScheme::tcp;
  ZmqHub hub(o);
  EXPECT_EQ(hub.endpoint().rfind("tcp://127.0.0.1:", 0), 0u);
  round_trip(hub);
  o.tcp_host = "0.0.0.0";
  EXPECT_THROW(ZmqHub{o}, InputError);
}

TEST(ZmqTransport, ReceiveTimesOutWithNothing) {
  ZmqHub hub;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(hub.receive(50ms));
  EXPECT_GE(std::chrono::steady_clock::now() - start, 45ms);
}

TEST(ZmqTransport, SendingToAnUnknownPeerIsAProtocolError) {
  ZmqHub hub;
  EXPECT_THROW(
      hub.send("nobody", make_text_message(MessageType::finish, "j", coupler_peer, 0, 0.0, "")),
      ProtocolError);
}

// A second client under the same participant name gets its own connection:
// messages it sends are not the admitted participant's, and what is sent to
// the participant never reaches it.
TEST(ZmqTransport, AnotherConnectionCannotTakeOverAnAdmittedName) {
  ZmqHub hub;
  ZmqClient real(hub.endpoint(), "water");
  real.send(coupler_peer, make_text_message(MessageType::hello, "j", "water", 0, 0.0, "{}"));
  auto hello = hub.receive(5s);
  ASSERT_TRUE(hello);
  hub.admit(hello->peer, "water");
  ZmqClient impostor(hub.endpoint(), "water");
  impostor.send(coupler_peer, make_text_message(MessageType::hello, "j", "water", 0, 0.0, "{}"));
  auto from_impostor = hub.receive(5s);
  ASSERT_TRUE(from_impostor);
  EXPECT_FALSE(from_impostor->admitted);
  EXPECT_NE(from_impostor->peer, "water");
  hub.send("water", make_text_message(MessageType::finish, "j", coupler_peer, 1, 0.0, "yours"));
  EXPECT_TRUE(real.receive(5s));
  EXPECT_FALSE(impostor.receive(200ms));
}

// Garbage from a connection that is not a participant comes back as
// `malformed`, never as an exception; from an admitted participant it is a
// ProtocolError naming it.
TEST(ZmqTransport, MalformedFramesOfStrangersAreReportedNotThrown) {
  ZmqHub hub;
  ZmqClient client(hub.endpoint(), "water");
  Message foreign = make_text_message(MessageType::hello, "j", "water", 0, 0.0, "{}");
  foreign.header.version = protocol_version + 1;
  client.send(coupler_peer, foreign);
  auto r = hub.receive(5s);
  ASSERT_TRUE(r);
  ASSERT_TRUE(r->malformed);
  EXPECT_THAT(*r->malformed, ::testing::HasSubstr("protocol version"));
  hub.admit(r->peer, "water");
  client.send(coupler_peer, foreign);
  EXPECT_THROW(hub.receive(5s), ProtocolError);
}

TEST(ZmqTransport, ClientRefusesAnEndpointThatIsNotZeroMq) {
  EXPECT_THROW(ZmqClient("http://127.0.0.1:80", "x"), InputError);
}

}  // namespace
}  // namespace cosim::com
