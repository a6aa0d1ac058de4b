#include "checkpoint/schedule.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "cosim/error.hpp"

namespace cosim::checkpoint {
namespace {

std::vector<std::size_t> due_windows(const Schedule& s, std::size_t windows, double length) {
  std::vector<std::size_t> due;
  for (std::size_t w = 0; w <= windows; ++w)
    if (s.due(w, length)) due.push_back(w);
  return due;
}

TEST(CheckpointSchedule, EveryNWindows) {
  EXPECT_EQ(due_windows(Schedule::parse("4"), 13, 0.1), (std::vector<std::size_t>{4, 8, 12}));
}

// Windows of 0.01 s every 0.03 s: the multiples of 0.03 land on window ends
// that floating point puts a hair either side of them.
TEST(CheckpointSchedule, EverySimulatedIntervalAtTheFirstWindowEndReachingIt) {
  EXPECT_EQ(due_windows(Schedule::parse("0.03s"), 10, 0.01), (std::vector<std::size_t>{3, 6, 9}));
  // An interval that is not a multiple of the window: the first end past it.
  EXPECT_EQ(due_windows(Schedule::parse("0.025s"), 10, 0.01),
            (std::vector<std::size_t>{3, 5, 8, 10}));
}

TEST(CheckpointSchedule, AnythingElseIsRefusedNamingTheOption) {
  for (const char* bad : {"", "0", "-2", "1.5", "abc", "0s", "-1s", "1e400s", "5ss", "s"}) {
    try {
      (void)Schedule::parse(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("--checkpoint-every"));
    }
  }
}

}  // namespace
}  // namespace cosim::checkpoint
