#include "cosim/io/state_file.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "same_bits.hpp"
#include "scratch_directory.hpp"

namespace cosim {
namespace {

namespace fs = std::filesystem;
using testing::same_bits;
using testing::ScratchDirectory;

struct SampleState {
  std::vector<double> depth{1.0, -0.0, std::numeric_limits<double>::quiet_NaN(), 1e-310, 3.5};
  std::vector<std::int64_t> body{0, 1, -7, std::numeric_limits<std::int64_t>::max()};
  std::vector<Eigen::Vector2d> position{{0.1, 0.2}, {0.3, 0.4}, {-1.0, 2.0}};
  std::vector<Eigen::Matrix2d> gradient{Eigen::Matrix2d::Identity(), Eigen::Matrix2d::Zero()};
  std::vector<std::array<double, 2>> internal{{1.0, 2.0}};
  double time = 0.123456789;
  std::int64_t steps = 4242;

  void write(const fs::path& file) const {
    StateFileWriter out(file, "sample_solver", 3);
    out.numbers("depth", depth);
    out.integers("body", body);
    out.rows("position", position);
    out.rows("gradient", gradient);
    out.rows("internal", internal);
    out.number("time", time);
    out.integer("steps", steps);
    out.commit();
  }
};

ExitCode code_of_reading(const fs::path& file, const char* kind = "sample_solver",
                         std::int64_t version = 3) {
  try {
    const StateFileReader in(file, kind, version);
    std::vector<double> depth;
    in.numbers("depth", 5, depth);
  } catch (const Error& e) {
    return e.code();
  }
  return ExitCode::success;
}

TEST(StateFile, ReadsBackEveryArrayBitForBit) {
  const ScratchDirectory dir;
  const SampleState written;
  written.write(dir / "state.h5");

  const StateFileReader in(dir / "state.h5", "sample_solver", 3);
  SampleState read;
  read.depth.clear();
  read.position.clear();
  in.numbers("depth", written.depth.size(), read.depth);
  in.integers("body", written.body.size(), read.body);
  in.rows("position", written.position.size(), read.position);
  in.rows("gradient", written.gradient.size(), read.gradient);
  in.rows("internal", written.internal.size(), read.internal);
  EXPECT_TRUE(same_bits(read.depth, written.depth));  // NaN, -0 and a subnormal included
  EXPECT_EQ(read.body, written.body);
  EXPECT_TRUE(same_bits(read.position, written.position));
  EXPECT_TRUE(same_bits(read.gradient, written.gradient));
  EXPECT_TRUE(same_bits(read.internal, written.internal));
  EXPECT_EQ(in.number("time"), written.time);
  EXPECT_EQ(in.integer("steps"), written.steps);
  EXPECT_TRUE(in.has("depth"));
  EXPECT_FALSE(in.has("pressure"));
}

TEST(StateFile, NothingIsLeftWithoutCommit) {
  const ScratchDirectory dir;
  {
    StateFileWriter out(dir / "state.h5", "sample_solver", 3);
    out.number("time", 1.0);
  }
  EXPECT_TRUE(fs::is_empty(dir.path())) << "a writer destroyed before commit() left files";
}

TEST(StateFile, RefusesAnotherKindOrVersionAMissingOrWrongSizedArrayAndATruncatedFile) {
  const ScratchDirectory dir;
  SampleState{}.write(dir / "state.h5");
  EXPECT_EQ(code_of_reading(dir / "state.h5"), ExitCode::success);
  EXPECT_EQ(code_of_reading(dir / "state.h5", "other_solver"), ExitCode::bad_input);
  EXPECT_EQ(code_of_reading(dir / "state.h5", "sample_solver", 4), ExitCode::bad_input);
  EXPECT_EQ(code_of_reading(dir / "absent.h5"), ExitCode::bad_input);

  const StateFileReader in(dir / "state.h5", "sample_solver", 3);
  std::vector<double> values;
  try {
    in.numbers("depth", 6, values);
    FAIL() << "read 5 values as 6";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_NE(std::string(e.what()).find("array 'depth' holds 5 values where 6 are expected"),
              std::string::npos)
        << e.what();
  }
  try {
    in.numbers("pressure", 5, values);
    FAIL() << "read a missing array";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("array 'pressure' is missing"), std::string::npos)
        << e.what();
  }
  std::vector<Eigen::Vector3d> rows;
  EXPECT_THROW(in.rows("position", 3, rows), Error);  // rows of 2, not 3

  const auto size = fs::file_size(dir / "state.h5");
  fs::copy_file(dir / "state.h5", dir / "truncated.h5");
  fs::resize_file(dir / "truncated.h5", size / 2);
  EXPECT_EQ(code_of_reading(dir / "truncated.h5"), ExitCode::bad_input);
}

}  // namespace
}  // namespace cosim
