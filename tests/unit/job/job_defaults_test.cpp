// The job schema is the one place a default is stated: every default is a
// value its own key accepts, and a job that leaves a key out reads it.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "exchange/drag_law_registry.hpp"
#include "job/job.hpp"
#include "schema_default.hpp"
#include "scratch_directory.hpp"

namespace cosim::job {
namespace {

namespace fs = std::filesystem;

template <class T>
T schema_default(const std::string& key_path) {
  return cosim::testing::schema_default<T>(job_schema(), key_path);
}

TEST(JobSchemaDefaults, EveryDefaultIsAcceptedByItsKey) {
  EXPECT_NO_THROW(job_schema().check_defaults());
  const auto& drag_laws = exchange::DragLawRegistry::instance();
  for (const std::string& law : drag_laws.types()) {
    EXPECT_NO_THROW(drag_laws.schema(law).check_defaults()) << law;
  }
}

TEST(JobSchemaDefaults, AJobWithoutTheOptionalKeysReadsTheSchemaDefaults) {
  const cosim::testing::ScratchDirectory dir;
  const Job job = load_job(dir.write("job.yaml",
                                     "kind: job\nname: bare\nend_time: 1.0\nwindow: 0.1\n"
                                     "participants:\n  soil: {executable: mpm_solver}\n"));

  EXPECT_EQ(job.start_time, schema_default<double>("start_time"));
  EXPECT_EQ(job.transport == TransportKind::mpi ? "mpi" : "zmq",
            schema_default<std::string>("transport"));
  EXPECT_EQ(job.zmq.scheme, schema_default<std::string>("zmq.scheme"));
  EXPECT_EQ(job.zmq.host, schema_default<std::string>("zmq.host"));
  EXPECT_EQ(job.zmq.allow_non_loopback, schema_default<bool>("zmq.allow_non_loopback"));
  EXPECT_EQ(job.extrapolation == com::Extrapolation::linear ? "linear" : "constant",
            schema_default<std::string>("extrapolation"));
  EXPECT_EQ(job.window_timeout_s, schema_default<double>("window_timeout"));
  EXPECT_EQ(job.stability.refuse_above, schema_default<double>("stability_check.refuse_above"));
  EXPECT_EQ(job.stability.accept_unstable, schema_default<bool>("stability_check.accept_unstable"));
  EXPECT_EQ(job.output_every, schema_default<double>("output.every"));
  EXPECT_EQ(job.exchanges.size(), schema_default<std::vector<std::string>>("exchange").size());
  EXPECT_EQ(schema_default<std::string>("momentum_exchange"), "none");
  EXPECT_FALSE(job.momentum_exchange.has_value());
  const ParticipantSpec& soil = job.participants.at(0);
  EXPECT_EQ(soil.args, schema_default<std::vector<std::string>>("participants.<name>.args"));
  EXPECT_EQ(soil.ranks, schema_default<int>("participants.<name>.ranks"));
  EXPECT_EQ(soil.ranks, 1);
  EXPECT_TRUE(soil.meshes.empty());
  EXPECT_EQ(job_schema().default_of("participants.<name>.meshes"), "{}");
  EXPECT_EQ(job_schema().default_of("momentum_exchange.solved_by"), "coupler");
  EXPECT_EQ(job_schema().default_of("exchange.[].mapping.kernel"), "linear");
  EXPECT_EQ(schema_default<std::string>("coupling.scheme"), "parallel-explicit");
  EXPECT_FALSE(job.coupling.is_implicit());
  EXPECT_FALSE(job.coupling.is_serial());
}

TEST(JobSchemaDefaults, AnImplicitJobReadsTheCouplingAndAccelerationDefaults) {
  const cosim::testing::ScratchDirectory dir;
  const Job job = load_job(dir.write(
      "job.yaml",
      "kind: job\nname: bare\nend_time: 1.0\nwindow: 0.1\n"
      "participants:\n  a: {executable: x, meshes: {g: {kind: uniform_grid, dim: 1}}, writes: {p: "
      "g}, reads: {q: g}}\n"
      "  b: {executable: x, meshes: {g: {kind: uniform_grid, dim: 1}}, writes: {q: g}, reads: {p: "
      "g}}\n"
      "exchange:\n  - {field: p, from: a, to: b, mapping: consistent}\n"
      "  - {field: q, from: b, to: a, mapping: consistent}\n"
      "coupling:\n  scheme: parallel-implicit\n  convergence: [{field: b.p, relative: 1e-6}]\n"));
  const CouplingSpec& c = job.coupling;
  EXPECT_TRUE(c.is_implicit());
  EXPECT_EQ(c.time_interpolation == com::TimeInterpolation::linear ? "linear" : "constant",
            schema_default<std::string>("coupling.time_interpolation"));
  EXPECT_EQ(c.max_iterations, schema_default<std::size_t>("coupling.max_iterations"));
  EXPECT_EQ(c.on_max_iterations == OnMaxIterations::stop ? "stop" : "continue",
            schema_default<std::string>("coupling.on_max_iterations"));
  EXPECT_EQ(c.divergence_factor, schema_default<double>("coupling.divergence_factor"));
  const acceleration::AccelerationSpec& a = c.acceleration;
  EXPECT_EQ(a.method == acceleration::Method::iqn_ils ? "iqn-ils" : "other",
            schema_default<std::string>("coupling.acceleration.method"));
  EXPECT_EQ(a.relaxation, schema_default<double>("coupling.acceleration.relaxation"));
  EXPECT_EQ(a.max_columns, schema_default<std::size_t>("coupling.acceleration.max_columns"));
  EXPECT_EQ(a.reuse_windows, schema_default<std::size_t>("coupling.acceleration.reuse_windows"));
  EXPECT_EQ(a.filter == acceleration::Filter::qr2 ? "qr2" : "other",
            schema_default<std::string>("coupling.acceleration.filter"));
  EXPECT_EQ(a.filter_limit, schema_default<double>("coupling.acceleration.filter_limit"));
  EXPECT_EQ(
      a.preconditioner == acceleration::Preconditioner::residual_sum ? "residual-sum" : "other",
      schema_default<std::string>("coupling.acceleration.preconditioner"));
  EXPECT_EQ(a.freeze_preconditioner_after,
            schema_default<std::size_t>("coupling.acceleration.freeze_preconditioner_after"));
  // Every field the coupler sends, measured or not, in participant order.
  ASSERT_EQ(c.accelerated.size(), 2u);
  EXPECT_EQ(c.accelerated[0].label(), "a.q");
  EXPECT_EQ(c.accelerated[1].label(), "b.p");
}

}  // namespace
}  // namespace cosim::job
