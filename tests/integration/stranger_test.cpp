// Strangers on a run's endpoint: over tcp any local user can connect to the
// coupler's port. Without the run token a process cannot join, cannot take a
// participant's place or receive its fields, and garbage it writes is
// logged and dropped; the run goes on to its end undisturbed.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <thread>
#include <zmq.hpp>

#include "com/handshake.hpp"
#include "com/zmq_transport.hpp"
#include "demo_job.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The log's text once it holds `marker`, or empty after the timeout.
std::string log_once_it_says(const fs::path& log, const std::string& marker,
                             std::chrono::seconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (Clock::now() < deadline) {
    std::string text = read_text(log);
    if (text.find(marker) != std::string::npos) return text;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return {};
}

// The coupler's endpoint, from the line its log gives it.
std::string endpoint_of(const fs::path& log) {
  const std::string marker = "zeromq hub at ";
  const std::string text = log_once_it_says(log, marker, std::chrono::seconds(30));
  const auto at = text.find(marker);
  if (at == std::string::npos) return {};
  const auto start = at + marker.size();
  return text.substr(start, text.find_first_of(" \n", start) - start);
}

class Strangers : public ::testing::TestWithParam<std::string> {};

TEST_P(Strangers, CannotJoinStallOrReadARun) {
  const fs::path dir = fresh_directory("stranger_" + GetParam());
  JobOptions o;
  o.scheme = GetParam();
  o.end_time = 20.0;  // 8000 windows: the strangers act while it runs
  const fs::path job = write_job(dir, o);
  const fs::path run = dir / "run";
  const pid_t cosim = spawn(
      {binary("cosim").string(), "run", job.string(), "--output", run.string()}, dir / "cosim.log");
  const std::string endpoint = endpoint_of(run / "log.txt");
  ASSERT_FALSE(endpoint.empty());
  ASSERT_FALSE(log_once_it_says(run / "log.txt", "participants connected", std::chrono::seconds(30))
                   .empty());
  const auto summary = nlohmann::json::parse(read_text(run / "summary.json"));
  const std::string job_id = summary["job"]["id"];
  const std::string config_hash = summary["config"]["hash"];

  // 1. A hello as 'right', right job and config, no token, once the run
  //    has started: refused, and nothing of the run's data comes its way.
  //    (Admission without the token: handshake_test.)
  com::ZmqClient impostor(endpoint, "right");
  com::Hello hello;
  hello.participant = "right";
  hello.config_hash = config_hash;
  hello.program = "impostor";
  impostor.send(com::coupler_peer, com::make_text_message(com::MessageType::hello, job_id, "right",
                                                          0, 0.0, com::to_json(hello)));
  const auto reply = impostor.receive(std::chrono::seconds(10));
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->message.header.type, com::MessageType::refuse);

  // 2. A window message signed 'right' from the impostor's connection.
  impostor.send(com::coupler_peer,
                com::make_field_message(job_id, "right", 5, 0.0, "pressure", "grid",
                                        std::vector<double>(98, 1.0), 1));
  // 3. Garbage: a lone frame, too many frames, a header of another protocol.
  zmq::context_t context;
  zmq::socket_t raw(context, zmq::socket_type::dealer);
  raw.set(zmq::sockopt::linger, 0);
  raw.connect(endpoint);
  raw.send(zmq::str_buffer("garbage"), zmq::send_flags::none);
  raw.send(zmq::str_buffer("a"), zmq::send_flags::sndmore);
  raw.send(zmq::str_buffer("b"), zmq::send_flags::sndmore);
  raw.send(zmq::str_buffer("c"), zmq::send_flags::none);
  com::Message foreign =
      com::make_text_message(com::MessageType::hello, job_id, "left", 0, 0.0, "{}");
  foreign.header.version = com::protocol_version + 7;
  const auto header = com::encode_header(foreign.header);
  raw.send(zmq::buffer(header.data(), header.size()), zmq::send_flags::sndmore);
  raw.send(zmq::str_buffer("{}"), zmq::send_flags::none);

  const auto r = wait_for(cosim, dir / "cosim.log", std::chrono::seconds(120));
  EXPECT_EQ(r.exit_code, 0) << r.output << read_text(run / "log.txt");
  // The impostor got its refusal and nothing else.
  const auto more = impostor.receive(std::chrono::milliseconds(200));
  EXPECT_FALSE(more) << "the impostor received a '" << com::to_string(more->message.header.type)
                     << "' message";
  const std::string log = read_text(run / "log.txt");
  EXPECT_THAT(log, HasSubstr("not a participant of this run"));
  EXPECT_THAT(log, HasSubstr("a late hello as 'right'"));
  EXPECT_THAT(log, HasSubstr("a malformed message"));
  // Both participants ran every window.
  EXPECT_EQ(read_csv(run / "right" / "temperature_read.csv").size(), 8000u);
  EXPECT_EQ(read_csv(run / "left" / "pressure_read.csv").size(), 8000u);
}

INSTANTIATE_TEST_SUITE_P(Reliability, Strangers, ::testing::Values("tcp", "ipc"));

}  // namespace
}  // namespace cosim::testing
