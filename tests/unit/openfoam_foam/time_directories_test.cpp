#include "openfoam/foam/time_directories.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "scratch_directory.hpp"

namespace openfoam {
namespace {

namespace fs = std::filesystem;

struct NamedTime {
  double time;
  int precision;
  const char* name;
};

TEST(OpenFoamTimeName, MatchesPrintfGeneralFormat) {
  const std::vector<NamedTime> table{
      {0.05, 8, "0.05"},
      {1e-05, 8, "1e-05"},
      {2.0, 8, "2"},
      {0.0, 8, "0"},
      {0.1 + 0.2, 8, "0.3"},  // the sum's last-bit error is below the precision
      {0.1 + 0.2, 17, "0.30000000000000004"},
      {123456789.0, 8, "1.2345679e+08"},
      {100000.0, 6, "100000"},
      {1e6, 6, "1e+06"},
      {0.0001, 6, "0.0001"},
      {0.00001234, 6, "1.234e-05"},
      {1.5, 1, "2"},
      {0.123456789, 6, "0.123457"},
      // Names OpenFOAM v1912 wrote with timePrecision 6 (damBreak, cavity, column).
      {0.1, 6, "0.1"},
      {0.005, 6, "0.005"},
      {0.0002, 6, "0.0002"},
      {3 * 0.0002, 6, "0.0006"},
  };
  for (const NamedTime& t : table) {
    EXPECT_EQ(time_name(t.time, t.precision), t.name) << t.time << " at precision " << t.precision;
  }
}

class OpenFoamTimeDirectories : public ::testing::Test {
 protected:
  void make_directories(const std::vector<std::string>& names) const {
    for (const std::string& name : names) fs::create_directories(case_ / name);
  }
  void make_file(const std::string& name) const { std::ofstream(case_ / name) << "x\n"; }

  static std::vector<std::string> names_of(const std::vector<TimeDirectory>& directories) {
    std::vector<std::string> names;
    for (const TimeDirectory& d : directories) names.push_back(d.name);
    return names;
  }

  cosim::testing::ScratchDirectory scratch_;
  fs::path case_ = scratch_.path();
};

TEST_F(OpenFoamTimeDirectories, ListsNumericDirectoriesSortedByTime) {
  make_directories({"constant", "system", "processor0", "0.orig", "10", "0.1", "2", "0", "1e-05",
                    "0.05", "-0.5", "1e-05x", "inf", "nan", "postProcessing", "0.05/uniform"});
  make_file("3");
  make_file(".0.1.tmp");
  const std::vector<TimeDirectory> found = time_directories(case_);
  EXPECT_EQ(names_of(found),
            (std::vector<std::string>{"-0.5", "0", "1e-05", "0.05", "0.1", "2", "10"}));
  ASSERT_EQ(found.size(), 7u);
  EXPECT_EQ(found[2].time, 1e-05);
  EXPECT_EQ(found[3].time, 0.05);
}

TEST_F(OpenFoamTimeDirectories, EqualTimesComeInNameOrder) {
  make_directories({"0.10", "0.1", "1e-1"});
  EXPECT_EQ(names_of(time_directories(case_)), (std::vector<std::string>{"0.1", "0.10", "1e-1"}));
}

TEST_F(OpenFoamTimeDirectories, LatestIsTheLargestTime) {
  EXPECT_FALSE(latest_time_directory(case_).has_value());
  make_directories({"constant", "0", "0.9", "0.25"});
  const std::optional<TimeDirectory> latest = latest_time_directory(case_);
  ASSERT_TRUE(latest.has_value());
  EXPECT_EQ(latest->name, "0.9");
  EXPECT_EQ(latest->time, 0.9);
}

TEST_F(OpenFoamTimeDirectories, RemovesAllButTheKeptOnes) {
  make_directories(
      {"0", "0.05/lagrangian/kinematicCloud", "0.1/uniform", "0.15", "constant", "system"});
  std::ofstream(case_ / "0.05/lagrangian/kinematicCloud/positions") << "0()\n";
  make_file("log.interFoam");
  const std::vector<std::string> keep{"0", "0.15"};
  const std::vector<TimeDirectory> removed = remove_time_directories_except(case_, keep);
  EXPECT_EQ(names_of(removed), (std::vector<std::string>{"0.05", "0.1"}));
  EXPECT_EQ(names_of(time_directories(case_)), (std::vector<std::string>{"0", "0.15"}));
  EXPECT_FALSE(fs::exists(case_ / "0.05"));
  EXPECT_TRUE(fs::is_directory(case_ / "constant"));
  EXPECT_TRUE(fs::is_directory(case_ / "system"));
  EXPECT_TRUE(fs::exists(case_ / "log.interFoam"));
  EXPECT_TRUE(remove_time_directories_except(case_, keep).empty());
}

TEST_F(OpenFoamTimeDirectories, MissingCaseIsAParticipantFailureNamingIt) {
  const fs::path missing = case_ / "no_such_case";
  try {
    time_directories(missing);
    FAIL() << "no error";
  } catch (const cosim::Error& e) {
    EXPECT_EQ(cosim::to_int(e.code()), cosim::to_int(cosim::ExitCode::participant_failed));
    EXPECT_NE(std::string(e.what()).find("'" + missing.string() + "'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace openfoam
