#include "com/message.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>

#include "com/handshake.hpp"
#include "cosim/error.hpp"

namespace cosim::com {
namespace {

using ::testing::HasSubstr;

Header sample_header() {
  Header h;
  h.type = MessageType::field;
  h.element = ElementType::float64;
  h.job_id = "job-1";
  h.sender = "soil";
  h.window = 42;
  h.time = 0.125;
  h.field = "solid_velocity";
  h.mesh = "mpm_grid";
  h.count = 3;
  h.components = 2;
  return h;
}

TEST(MessageHeader, RoundTripsEveryField) {
  const Header h = sample_header();
  const Header d = decode_header(encode_header(h), "peer");
  EXPECT_EQ(d.version, protocol_version);
  EXPECT_EQ(d.type, h.type);
  EXPECT_EQ(d.element, h.element);
  EXPECT_EQ(d.job_id, h.job_id);
  EXPECT_EQ(d.sender, h.sender);
  EXPECT_EQ(d.window, h.window);
  EXPECT_EQ(d.time, h.time);
  EXPECT_EQ(d.field, h.field);
  EXPECT_EQ(d.mesh, h.mesh);
  EXPECT_EQ(d.count, h.count);
  EXPECT_EQ(d.components, h.components);
}

TEST(MessageHeader, IsLittleEndianOnTheWire) {
  Header h = sample_header();
  h.window = 0x0102030405060708ULL;
  const auto bytes = encode_header(h);
  // magic(4) version(2) type(1) element(1) then the window, low byte first.
  EXPECT_EQ(bytes[8], std::byte{0x08});
  EXPECT_EQ(bytes[15], std::byte{0x01});
}

TEST(MessageHeader, RejectsTruncatedForeignAndOtherVersionHeadersNamingThePeer) {
  auto bytes = encode_header(sample_header());
  for (std::size_t cut : {std::size_t{0}, std::size_t{3}, std::size_t{10}, bytes.size() - 1}) {
    try {
      decode_header(std::span(bytes).first(cut), "water");
      FAIL() << "accepted a header cut at " << cut;
    } catch (const ProtocolError& e) {
      EXPECT_EQ(e.peer(), "water");
      EXPECT_THAT(e.what(), HasSubstr("from 'water'"));
    }
  }
  auto foreign = bytes;
  foreign[0] = std::byte{'X'};
  EXPECT_THROW(decode_header(foreign, "water"), ProtocolError);
  Header other = sample_header();
  other.version = protocol_version + 1;
  try {
    decode_header(encode_header(other), "water");
    FAIL();
  } catch (const ProtocolError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr(fmt::format("speaks cosim protocol version {}, this side speaks {}",
                                      protocol_version + 1, protocol_version)));
  }
  auto trailing = bytes;
  trailing.push_back(std::byte{0});
  EXPECT_THROW(decode_header(trailing, "water"), ProtocolError);
  auto bad_type = bytes;
  bad_type[6] = std::byte{200};
  EXPECT_THROW(decode_header(bad_type, "water"), ProtocolError);
}

TEST(MessagePayload, SizeMustMatchTheHeader) {
  const std::vector<double> values{1, 2, 3, 4, 5, 6};
  Message m = make_field_message("job-1", "soil", 1, 0.0, "u", "grid", values, 2);
  EXPECT_EQ(m.header.count, 3u);
  EXPECT_NO_THROW(validate_payload(m, "soil", false));
  m.header.count = 4;
  EXPECT_THROW(validate_payload(m, "soil", false), ProtocolError);
  m.header.count = 3;
  m.header.components = 0;
  EXPECT_THROW(validate_payload(m, "soil", false), ProtocolError);
}

TEST(MessagePayload, SharedValuesAreSentWithoutACopyAndStayAlive) {
  auto values = std::make_shared<const std::vector<double>>(std::vector<double>{1.5, -2.0, 3.25});
  const double* data = values->data();
  const Message m = make_field_message("job-1", "coupler", 2, 0.5, "p", "grid", values, 1);
  values.reset();  // the message alone keeps them
  EXPECT_EQ(reinterpret_cast<const double*>(m.payload.bytes().data()), data);
  EXPECT_EQ(m.header.count, 3u);
  EXPECT_NO_THROW(validate_payload(m, "coupler", false));
  EXPECT_EQ(m.payload.doubles(), (std::vector<double>{1.5, -2.0, 3.25}));
}

TEST(MessagePayload, NonFiniteValuesAreRejectedUnlessTheFieldAllowsThem) {
  std::vector<double> values{1.0, std::numeric_limits<double>::quiet_NaN(), 3.0};
  const Message m = make_field_message("job-1", "water", 1, 0.0, "p", "grid", values, 1);
  try {
    validate_payload(m, "water", false);
    FAIL();
  } catch (const ProtocolError& e) {
    EXPECT_THAT(e.what(), HasSubstr("non-finite value at element 1"));
  }
  EXPECT_NO_THROW(validate_payload(m, "water", true));
  EXPECT_TRUE(std::isnan(m.payload.doubles()[1]));
}

TEST(MeshMessage, RoundTripsEveryMeshKind) {
  const std::vector<Mesh> meshes{
      {"grid", UniformGrid{3, {0.5, -1, 2}, {0.1, 0.2, 0.3}, {4, 5, 6}, GridLocation::node}},
      {"line", NonUniformLine{{0.0, 0.1, 0.25, 0.7}}},
      {"particles", PointCloud{2, {0.1, 0.2, 0.3, 0.4}, {0.01, 0.02}}},
      {"cells", CellCloud{3, {1, 2, 3}, {0.5}}}};
  for (const Mesh& mesh : meshes) {
    const Mesh back = decode_mesh_message(make_mesh_message("j", "p", 0, 0.0, mesh), "p");
    EXPECT_EQ(back.name, mesh.name);
    EXPECT_EQ(back.kind(), mesh.kind());
    EXPECT_EQ(back.dimension(), mesh.dimension());
    ASSERT_EQ(back.size(), mesh.size());
    for (std::size_t e = 0; e < mesh.size(); ++e) {
      EXPECT_EQ(back.position(e), mesh.position(e));
      EXPECT_EQ(back.control_volume(e), mesh.control_volume(e));
    }
  }
}

TEST(MeshMessage, RejectsGeometryThatIsNotAMesh) {
  Mesh bad{"line", NonUniformLine{{0.0, 0.2, 0.1}}};
  EXPECT_THROW(decode_mesh_message(make_mesh_message("j", "p", 0, 0.0, bad), "p"), ProtocolError);
}

// Numbers that must be whole (a pid, a dimension, a component count) are
// refused when they are floats, negative or beyond their range, never
// converted (1e300 to int is undefined behaviour).
TEST(Handshake, AHelloWithNumbersOutOfRangeIsMalformed) {
  const std::string field =
      R"({"name": "p", "mesh": "m", "components": COMPONENTS, "unit": "Pa", "quantity": )"
      R"("intensive", "time": "state", "allow_nonfinite": false})";
  const auto hello = [&](const std::string& pid, const std::string& dim,
                         const std::string& components) {
    std::string f = field;
    f.replace(f.find("COMPONENTS"), 10, components);
    return R"({"participant": "s", "config_hash": "0", "program": "x", "pid": )" + pid +
           R"(, "meshes": [{"name": "m", "kind": "uniform_grid", "dim": )" + dim +
           R"(}], "writes": [)" + f +
           R"(], "reads": [], "repeatable": false, "checkpointable": false, )"
           R"("restart_window": 0})";
  };
  EXPECT_NO_THROW(parse_hello(hello("12", "2", "1"), "s"));
  for (const auto& [pid, dim, components] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"1e300", "2", "1"},
           {"-5", "2", "1"},
           {"18446744073709551615", "2", "1"},
           {"12", "1e300", "1"},
           {"12", "2.5", "1"},
           {"12", "4", "1"},
           {"12", "2", "4294967297"},
           {"12", "2", "-1e300"}})
    EXPECT_THROW(parse_hello(hello(pid, dim, components), "s"), ProtocolError)
        << pid << " " << dim << " " << components;
}

TEST(Handshake, HelloAndWelcomeRoundTrip) {
  Hello h;
  h.participant = "soil";
  h.config_hash = "00ff";
  h.program = "mpm_solver";
  h.pid = 77;
  h.meshes = {{"mpm_grid", MeshKind::uniform_grid, 2}};
  FieldSpec f;
  f.name = "solid_fraction";
  f.mesh = "mpm_grid";
  f.unit = "1";
  f.quantity = Quantity::extensive;
  f.lower_bound = 0.0;
  f.upper_bound = 0.64;
  h.writes = {f};
  FieldSpec optional_read = f;
  optional_read.name = "pore_pressure";
  optional_read.optional = true;
  h.reads = {optional_read};
  const Hello back = parse_hello(to_json(h), "soil");
  EXPECT_EQ(back.participant, "soil");
  ASSERT_EQ(back.writes.size(), 1u);
  EXPECT_EQ(back.writes[0].upper_bound, 0.64);
  EXPECT_EQ(back.writes[0].quantity, Quantity::extensive);
  EXPECT_FALSE(back.writes[0].optional);
  ASSERT_EQ(back.reads.size(), 1u);
  EXPECT_TRUE(back.reads[0].optional);
  EXPECT_THROW(parse_hello("{\"participant\": 3}", "soil"), ProtocolError);
  h.repeatable = true;
  EXPECT_TRUE(parse_hello(to_json(h), "soil").repeatable);
  h.checkpointable = true;
  h.restart_window = 500;
  EXPECT_TRUE(parse_hello(to_json(h), "soil").checkpointable);
  EXPECT_EQ(parse_hello(to_json(h), "soil").restart_window, 500u);
  Welcome w{.config_hash = "00ff",
            .start_time = 0.0,
            .end_time = 1.0,
            .window = 0.01,
            .extrapolation = Extrapolation::linear,
            .implicit = true,
            .time_interpolation = TimeInterpolation::linear,
            .timeout_s = 30.0,
            .sends = {"pore_pressure"}};
  const Welcome wb = parse_welcome(to_json(w), "coupler");
  EXPECT_TRUE(wb.implicit);
  EXPECT_EQ(wb.time_interpolation, TimeInterpolation::linear);
  EXPECT_EQ(wb.sends, std::vector<std::string>{"pore_pressure"});
  EXPECT_EQ(wb.window, 0.01);
  EXPECT_EQ(wb.config_hash, "00ff");
  EXPECT_EQ(wb.extrapolation, Extrapolation::linear);
  EXPECT_THROW(
      parse_welcome(
          R"({"config_hash":"0","start_time":0,"end_time":1,"window":-1,"extrapolation":"constant","implicit":false,"time_interpolation":"constant","timeout_s":1,"sends":[]})",
          "c"),
      ProtocolError);
}

}  // namespace
}  // namespace cosim::com
