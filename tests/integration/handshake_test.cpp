// The handshake refuses participants started for another job, another job
// config or another protocol version, with a message saying which.

#include "com/handshake.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <future>
#include <thread>

#include "com/zmq_transport.hpp"
#include "cosim/error.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/participant.hpp"
#include "cplscheme/coupler.hpp"
#include "job/job.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

constexpr const char* job_yaml = R"(kind: job
name: handshake
end_time: 0.01
window: 0.005
participants:
  solo:
    executable: cosim_test_participant
    meshes: {grid: {kind: uniform_grid, dim: 1}}
    writes: {}
)";

class Handshake : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        testing::fresh_directory(::testing::UnitTest::GetInstance()->current_test_info()->name());
    testing::write_text(dir_ / "job.yaml", job_yaml);
    job_ = job::load_job(dir_ / "job.yaml");
    summary_ = std::make_unique<RunSummary>(dir_, "handshake test");
    cplscheme::CouplerOptions options;
    options.output_dir = dir_;
    options.job_id = "the-job";
    options.connect_timeout_s = 20.0;
    options.tokens = tokens();
    coupler_ = std::make_unique<cplscheme::Coupler>(job_, hub_, nullptr, *summary_, options);
    result_ = std::async(std::launch::async, [this] {
      try {
        coupler_->run();
        return std::string("ok");
      } catch (const std::exception& e) {
        return std::string(e.what());
      }
    });
  }

  virtual std::map<std::string, std::string> tokens() const { return {}; }

  // A participant that does what the job expects, with the given identity.
  void run_participant(const std::string& job_id, const std::string& hash,
                       const std::string& token = {}) {
    CouplingEndpoint endpoint{hub_.endpoint(), "solo", job_id, hash, 20.0, token};
    Participant p("solo", endpoint);
    p.declare_mesh(Mesh{"grid", UniformGrid{1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1}}});
    p.initialize(0.0, 0.01);
    while (p.is_coupling_ongoing()) p.advance(std::min(0.002, p.max_time_step()));
    p.finalize();
  }

  fs::path dir_;
  job::Job job_;
  com::ZmqHub hub_;
  std::unique_ptr<RunSummary> summary_;
  std::unique_ptr<cplscheme::Coupler> coupler_;
  std::future<std::string> result_;
};

TEST_F(Handshake, AdmitsTheRightParticipant) {
  EXPECT_NO_THROW(run_participant("the-job", job_.config_hash));
  EXPECT_EQ(result_.get(), "ok");
}

TEST_F(Handshake, RefusesAParticipantOfAnotherJob) {
  try {
    run_participant("another-job", job_.config_hash);
    FAIL() << "admitted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_THAT(e.what(),
                HasSubstr("started for job 'another-job', this coupler runs job 'the-job'"));
  }
  run_participant("the-job", job_.config_hash);  // the real one is still admitted
  EXPECT_EQ(result_.get(), "ok");
}

TEST_F(Handshake, RefusesAParticipantOfAnotherConfig) {
  try {
    run_participant("the-job", "0123456789abcdef");
    FAIL() << "admitted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("config with hash 0123456789abcdef"));
    EXPECT_THAT(e.what(), HasSubstr(job_.config_hash));
  }
  run_participant("the-job", job_.config_hash);
  EXPECT_EQ(result_.get(), "ok");
}

TEST_F(Handshake, RefusesAnotherProtocolVersionSayingWhich) {
  {
    com::ZmqClient client(hub_.endpoint(), "solo");
    com::Message hello =
        com::make_text_message(com::MessageType::hello, "the-job", "solo", 0, 0.0, "{}");
    hello.header.version = com::protocol_version + 1;
    client.send(com::coupler_peer, hello);
    auto reply = client.receive(std::chrono::seconds(20));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->message.header.type, com::MessageType::refuse);
    EXPECT_THAT(reply->message.payload.text(),
                HasSubstr(fmt::format("speaks cosim protocol version {}, this side speaks {}",
                                      com::protocol_version + 1, com::protocol_version)));
  }
  run_participant("the-job", job_.config_hash);
  EXPECT_EQ(result_.get(), "ok");
}

TEST_F(Handshake, RefusesDeclarationsThatContradictTheJob) {
  CouplingEndpoint endpoint{hub_.endpoint(), "solo", "the-job", job_.config_hash, 20.0, ""};
  Participant p("solo", endpoint);
  p.declare_mesh(Mesh{"grid", UniformGrid{2, {0, 0, 0}, {0.1, 0.1, 1}, {10, 10, 1}}});
  try {
    p.initialize(0.0, 0.01);
    FAIL() << "admitted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("declares mesh 'grid' as a 2D uniform_grid, the job says 1D"));
  }
  run_participant("the-job", job_.config_hash);
  EXPECT_EQ(result_.get(), "ok");
}

// A read declared optional that the job does not send is admitted: the
// participant keeps its default and learns from is_sent() that it comes not;
// the same read, not optional, is refused, naming what to add to the job.
TEST_F(Handshake, AdmitsAnOptionalReadTheJobDoesNotSend) {
  CouplingEndpoint endpoint{hub_.endpoint(), "solo", "the-job", job_.config_hash, 20.0, ""};
  FieldSpec flux{.name = "solid_volume_flux", .mesh = "grid", .unit = "m/s"};
  {
    Participant p("solo", endpoint);
    p.declare_mesh(Mesh{"grid", UniformGrid{1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1}}});
    p.declare_read(flux, 0.0);
    try {
      p.initialize(0.0, 0.01);
      FAIL() << "admitted";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr("reads 'solid_volume_flux', which the job does not send"));
    }
  }
  Participant p("solo", endpoint);
  p.declare_mesh(Mesh{"grid", UniformGrid{1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1}}});
  flux.optional = true;
  p.declare_read(flux, 0.25);
  EXPECT_FALSE(p.is_sent("solid_volume_flux"));
  p.initialize(0.0, 0.01);
  EXPECT_FALSE(p.is_sent("solid_volume_flux"));
  while (p.is_coupling_ongoing()) {
    EXPECT_EQ(p.read("solid_volume_flux"), std::vector<double>(10, 0.25));
    p.advance(std::min(0.002, p.max_time_step()));
  }
  p.finalize();
  EXPECT_EQ(result_.get(), "ok");
}

// With run tokens (as `cosim run` hands them out), a hello without its
// participant's token is refused, even one that names the right job and
// config; the process holding the token is admitted after it.
class HandshakeWithTokens : public Handshake {
 protected:
  std::map<std::string, std::string> tokens() const override {
    return {{"solo", "0f1e2d3c4b5a69788796a5b4c3d2e1f0"}};
  }
};

TEST_F(HandshakeWithTokens, RefusesAHelloWithoutItsTokenAndAdmitsTheTokenHolder) {
  for (const std::string token : {"", "0f1e2d3c4b5a69788796a5b4c3d2e1f1"}) {
    try {
      run_participant("the-job", job_.config_hash, token);
      FAIL() << "admitted with token '" << token << "'";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::bad_input);
      EXPECT_THAT(e.what(), HasSubstr("admits only the processes it started"));
    }
  }
  run_participant("the-job", job_.config_hash, "0f1e2d3c4b5a69788796a5b4c3d2e1f0");
  EXPECT_EQ(result_.get(), "ok");
}

}  // namespace
}  // namespace cosim
