// Fuzzes the decoders of what a peer sends: message headers, payload checks,
// meshes, and the hello and welcome of the handshake. An input is one
// message as a transport receives it: a 4-byte little-endian header length,
// the header, then the payload. Every decoder must accept it or refuse it
// with a cosim::Error (ProtocolError), within the hang limit.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstring>
#include <iostream>

#include "com/handshake.hpp"
#include "com/message.hpp"
#include "cosim/error.hpp"
#include "fuzz_run.hpp"
#include "mutator.hpp"

namespace cosim::testing {
namespace {

using com::Message;
using com::MessageType;

constexpr std::size_t max_input_size = 1 << 14;

std::string framed(const com::Header& header, std::span<const std::byte> payload) {
  const std::vector<std::byte> encoded = com::encode_header(header);
  const auto length = static_cast<std::uint32_t>(encoded.size());
  std::string bytes;
  for (int i = 0; i < 4; ++i) bytes += static_cast<char>((length >> (8 * i)) & 0xff);
  bytes.append(reinterpret_cast<const char*>(encoded.data()), encoded.size());
  bytes.append(reinterpret_cast<const char*>(payload.data()), payload.size());
  return bytes;
}

std::string framed(const Message& message) {
  return framed(message.header, message.payload.bytes());
}

// The header and payload of a framed input; the header is decoded (and may
// be refused).
struct Unframed {
  com::Header header;
  std::span<const std::byte> payload;
};

Unframed unframed(const std::string& input) {
  if (input.size() < 4) throw ProtocolError("fuzz", "shorter than the frame's length");
  std::uint32_t length = 0;
  for (std::size_t i = 0; i < 4; ++i)
    length |= static_cast<std::uint32_t>(static_cast<unsigned char>(input[i])) << (8 * i);
  const std::size_t header_size = std::min<std::size_t>(length, input.size() - 4);
  const auto* bytes = reinterpret_cast<const std::byte*>(input.data());
  return {com::decode_header(std::span(bytes + 4, header_size), "fuzz"),
          std::span(bytes + 4 + header_size, input.size() - 4 - header_size)};
}

void decode(const std::string& input) {
  const Unframed parts = unframed(input);
  Message message;
  message.header = parts.header;
  message.payload = com::Payload::copy_of(parts.payload);
  for (const bool allow_nonfinite : {true, false}) {
    try {
      com::validate_payload(message, "fuzz", allow_nonfinite);
    } catch (const ProtocolError&) {
    }
  }
  switch (message.header.type) {
    case MessageType::mesh:
      (void)com::decode_mesh_message(message, "fuzz");
      break;
    case MessageType::hello:
      (void)com::parse_hello(message.payload.text(), "fuzz");
      break;
    case MessageType::welcome:
      (void)com::parse_welcome(message.payload.text(), "fuzz");
      break;
    default:
      break;
  }
}

std::vector<std::string> seeds() {
  std::vector<Message> messages;
  const auto add_mesh = [&](MeshGeometry geometry) {
    messages.push_back(
        com::make_mesh_message("job", "soil", 0, 0.0, Mesh{"grid", std::move(geometry)}));
  };
  add_mesh(UniformGrid{1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1}, GridLocation::cell});
  add_mesh(UniformGrid{2, {-1, 0, 0}, {0.5, 0.25, 1}, {4, 8, 1}, GridLocation::node});
  add_mesh(UniformGrid{3, {0, 0, 0}, {1, 1, 1}, {2, 3, 4}, GridLocation::cell});
  add_mesh(NonUniformLine{{0.0, 0.1, 0.3, 0.7, 1.5}});
  add_mesh(PointCloud{2, {0, 0, 1, 0, 0, 1}, {0.1, 0.1, 0.1}});
  add_mesh(PointCloud{3, {0, 0, 0, 1, 1, 1}, {0.5, 0.5}});
  add_mesh(CellCloud{3, {0.5, 0.5, 0.5}, {1.0}});
  add_mesh(CellCloud{1, {0.5, 1.5}, {1.0, 1.0}});

  com::Hello hello;
  hello.participant = "soil";
  hello.config_hash = "0123456789abcdef";
  hello.token = "secret";
  hello.program = "mpm_solver";
  hello.pid = 4242;
  hello.meshes = {{"grid", MeshKind::uniform_grid, 2}, {"particles", MeshKind::point_cloud, 3}};
  FieldSpec pressure;
  pressure.name = "pore_pressure";
  pressure.mesh = "grid";
  pressure.unit = "Pa";
  FieldSpec velocity = pressure;
  velocity.name = "solid_velocity";
  velocity.components = 2;
  velocity.unit = "m/s";
  velocity.lower_bound = -10.0;
  velocity.optional = true;
  hello.writes = {velocity};
  hello.reads = {pressure};
  messages.push_back(
      com::make_text_message(MessageType::hello, "job", "soil", 0, 0.0, com::to_json(hello)));

  com::Welcome welcome;
  welcome.config_hash = "0123456789abcdef";
  welcome.end_time = 1.0;
  welcome.window = 1e-3;
  welcome.sends = {"pore_pressure"};
  messages.push_back(com::make_text_message(MessageType::welcome, "job", "coupler", 0, 0.0,
                                            com::to_json(welcome)));

  const std::vector<double> values{1.0, -2.5, 0.0, 1e300, 3.0, 4.0};
  messages.push_back(
      com::make_field_message("job", "soil", 3, 0.003, "solid_velocity", "grid", values, 2));
  messages.push_back(
      com::make_field_message("job", "soil", 3, 0.003, "pore_pressure", "grid", values, 1));
  messages.push_back(
      com::make_text_message(MessageType::refuse, "job", "coupler", 0, 0.0, "wrong token"));
  messages.push_back(
      com::make_text_message(MessageType::abort, "job", "soil", 7, 0.007, "NaN in cell 3"));
  messages.push_back(com::make_text_message(MessageType::window_end, "job", "soil", 7, 0.007, ""));
  messages.push_back(com::make_text_message(MessageType::finish, "job", "coupler", 9, 0.009, ""));

  std::vector<std::string> inputs;
  for (const Message& message : messages) inputs.push_back(framed(message));
  return inputs;
}

// Half of the inputs set the header's numbers and kinds through the header
// itself (byte mutations rarely land two of them on their fields' offsets),
// half of those then mutated as bytes too.
std::string mutate_message(const std::string& original, Mutator& mutator) {
  std::string input = original;
  if (mutator.below(2) == 0) {
    try {
      Unframed parts = unframed(original);
      com::Header& h = parts.header;
      for (std::size_t changes = 1 + mutator.below(3); changes > 0; --changes) {
        switch (mutator.below(5)) {
          case 0:
            h.count = mutator.interesting_integer();
            break;
          case 1:
            h.components = static_cast<std::uint32_t>(mutator.interesting_integer());
            break;
          case 2:
            h.element = static_cast<com::ElementType>(mutator.below(3));
            break;
          case 3:
            h.type = static_cast<MessageType>(1 + mutator.below(9));
            break;
          case 4:
            h.window = mutator.interesting_integer();
            break;
        }
      }
      input = framed(h, parts.payload);
      if (mutator.below(2) == 0) return input;
    } catch (const ProtocolError&) {
      // a kept input whose header does not decode: bytes only
    }
  }
  return mutator.mutate(input, max_input_size);
}

FuzzTarget message_target() {
  FuzzTarget target;
  target.name = "message";
  target.run = decode;
  target.mutate = mutate_message;
  target.seeds = seeds();
  // JSON's structure, for the hello and welcome payloads.
  target.tokens = {"{",    "}",     "[",  "]",        ",",       ":",       "\"",     "null",
                   "true", "1e400", "-1", "[[[[[[[[", "{\"a\":", "\\u0000", "\\ud800"};
  target.max_size = max_input_size;
  target.default_executions = 100000;
  return target;
}

// What the fuzzer found, written out (the inputs it found are kept under
// tests/data/fuzz/message/ and replayed by every run).

com::Header float64_header(MessageType type, std::uint64_t count, std::uint32_t components) {
  com::Header h;
  h.type = type;
  h.element = com::ElementType::float64;
  h.field = type == MessageType::mesh ? "uniform_grid" : "pressure";
  h.mesh = "grid";
  h.count = count;
  h.components = components;
  return h;
}

TEST(MessageDecoders, CountTimesComponentsPastTwoTo64IsRefused) {
  // 2^33 x 2^29 values of 8 bytes: 2^65 bytes, 0 after wrapping, as sent.
  const Message message{float64_header(MessageType::field, std::uint64_t{1} << 33, 1u << 29), {}};
  EXPECT_THROW(com::validate_payload(message, "soil", false), ProtocolError);
}

TEST(MessageDecoders, MeshOrFieldWithoutFloat64ValuesIsRefused) {
  for (const auto element : {com::ElementType::none, com::ElementType::text}) {
    Message message{float64_header(MessageType::mesh, 1, 11), com::Payload::from_text("x")};
    message.header.element = element;
    message.header.count = element == com::ElementType::text ? 1 : 0;
    EXPECT_THROW((void)com::decode_mesh_message(message, "soil"), ProtocolError);
    message.header.type = MessageType::field;
    EXPECT_THROW(com::validate_payload(message, "soil", true), ProtocolError);
  }
}

// A uniform grid's record (see handshake.cpp): location, origin, spacing,
// cells, dimension.
Message grid_message(double cells, double dimension) {
  const std::vector<double> record{0, 0, 0, 0, 1, 1, 1, cells, cells, cells, dimension};
  Message message{float64_header(MessageType::mesh, 1, 11), com::Payload::from_doubles(record)};
  return message;
}

TEST(MessageDecoders, GridOfMoreThanTwoTo40ValuesIsRefused) {
  EXPECT_NO_THROW((void)com::decode_mesh_message(grid_message(1e4, 3), "soil"));
  try {
    (void)com::decode_mesh_message(grid_message(1e9, 3), "soil");
    ADD_FAILURE() << "a grid of 1e27 cells was accepted";
  } catch (const ProtocolError& e) {
    EXPECT_NE(std::string(e.what()).find("1e+27 grid values"), std::string::npos) << e.what();
  }
}

TEST(MessageDecoders, GridDimensionOutOfAnIntIsRefusedBeforeTheConversion) {
  for (const double dimension : {1e300, -1e300, 2.5, 0.0, 4.0}) {
    try {
      (void)com::decode_mesh_message(grid_message(2, dimension), "soil");
      ADD_FAILURE() << "dimension " << dimension << " was accepted";
    } catch (const ProtocolError& e) {
      EXPECT_NE(std::string(e.what()).find(fmt::format("dimension {}", dimension)),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(MessageFuzz, SeedsAreMessagesTheDecodersAccept) {
  for (const std::string& seed : message_target().seeds) EXPECT_NO_THROW(decode(seed));
}

TEST(MessageFuzz, MutatedMessagesDecodeOrAreRefusedWithoutCrashOrHang) {
  const FuzzTarget target = message_target();
  const FuzzReport report = fuzz(target);
  std::cout << report.summary(target.name) << '\n';
  for (const std::string& failure : report.failures) ADD_FAILURE() << failure;
  EXPECT_EQ(report.crashes, 0u);
  EXPECT_EQ(report.hangs, 0u);
}

}  // namespace
}  // namespace cosim::testing
