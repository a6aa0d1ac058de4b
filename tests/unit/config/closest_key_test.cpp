#include "cosim/config/closest_key.hpp"

#include <gtest/gtest.h>

namespace cosim::config {
namespace {

const std::vector<std::string> job_keys{
    "kind",         "name",     "end_time",          "window", "transport",
    "participants", "exchange", "momentum_exchange", "output"};

TEST(ConfigClosestKey, FindsOneTypoAwayKeys) {
  EXPECT_EQ(closest_key("end_tme", job_keys), "end_time");     // deletion
  EXPECT_EQ(closest_key("end_timee", job_keys), "end_time");   // insertion
  EXPECT_EQ(closest_key("wnidow", job_keys), "window");        // transposition
  EXPECT_EQ(closest_key("transprot", job_keys), "transport");  // transposition
  EXPECT_EQ(closest_key("participans", job_keys), "participants");
}

TEST(ConfigClosestKey, IgnoresCaseAndSeparatorSlips) {
  EXPECT_EQ(closest_key("EndTime", job_keys), "end_time");
  EXPECT_EQ(closest_key("end-time", job_keys), "end_time");
  EXPECT_EQ(closest_key("momentumexchange", job_keys), "momentum_exchange");
}

TEST(ConfigClosestKey, SuggestsNothingForUnrelatedNames) {
  EXPECT_FALSE(closest_key("solver", job_keys).has_value());
  EXPECT_FALSE(closest_key("x", job_keys).has_value());
  EXPECT_FALSE(closest_key("end_time", {}).has_value());
}

TEST(ConfigClosestKey, SuggestionListsTheChoicesWhenNothingIsClose) {
  EXPECT_EQ(suggestion("zqm", {"zmq", "mpi"}), "did you mean 'zmq'?");
  EXPECT_EQ(suggestion("tcp", {"zmq", "mpi"}), "expected one of: zmq, mpi");
}

}  // namespace
}  // namespace cosim::config
