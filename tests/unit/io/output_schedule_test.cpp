// The output schedule every solver writes its snapshots, gauges and probes
// by: it moves past any stretch of time at once, and refuses an interval
// that would give an absurd number of outputs.
#include "cosim/io/output_schedule.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <future>

#include "cosim/config/document.hpp"

namespace cosim {
namespace {

using ::testing::HasSubstr;

TEST(OutputSchedule, HitsEveryMultipleAndTheEnd) {
  OutputSchedule s(0.1, 0.35);
  const double tolerance = 1e-12;
  EXPECT_DOUBLE_EQ(s.next(), 0.1);
  s.passed(0.1, tolerance);
  EXPECT_DOUBLE_EQ(s.next(), 0.2);
  // 0.1 + 0.2 lands above 0.3 by round-off: still 0.3's output.
  EXPECT_TRUE(s.due(0.1 + 0.2, tolerance));
  s.passed(0.1 + 0.2, tolerance);
  EXPECT_DOUBLE_EQ(s.next(), 0.35);  // the end, before 0.4
  s.passed(0.35, tolerance);
  EXPECT_EQ(s.next(), std::numeric_limits<double>::infinity());
}

TEST(OutputSchedule, PassingSkipsEveryOutputTimeOnTheWay) {
  OutputSchedule s(0.1, 10.0);
  s.passed(0.549, 1e-12);
  EXPECT_DOUBLE_EQ(s.next(), 0.6);
  s.passed(0.6 - 1e-13, 1e-12);  // within the tolerance of 0.6
  EXPECT_DOUBLE_EQ(s.next(), 0.7);
  s.passed(0.2, 1e-12);  // never back
  EXPECT_DOUBLE_EQ(s.next(), 0.7);
}

TEST(OutputSchedule, ZeroIntervalIsTheEndOnly) {
  OutputSchedule s(0.0, 2.0);
  EXPECT_EQ(s.next(), 2.0);
  s.passed(1.0, 1e-12);
  EXPECT_EQ(s.next(), 2.0);
}

// Before: passed() stepped one interval at a time, so a schedule passed far
// beyond its intervals (here 10^15 of them) never returned. (An optimiser
// may drop that loop here, its count unused past the end; the sanitizer
// tree's test drivers, at -O0, kept it.)
TEST(OutputSchedule, PassingAnyStretchOfTimeTakesNoLoopPerInterval) {
  auto passed = std::async(std::launch::async, [] {
    OutputSchedule s(1e-6, 1.0);
    s.passed(1e9, 1e-10);
    return s.next();
  });
  if (passed.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
    ADD_FAILURE() << "OutputSchedule::passed(1e9) did not return within 20 s";
    std::_Exit(1);  // the hung thread cannot be joined
  }
  EXPECT_EQ(passed.get(), std::numeric_limits<double>::infinity());  // past the end
}

TEST(OutputSchedule, RefusesAnIntervalGivingMoreThanAMillionOutputs) {
  EXPECT_NO_THROW(OutputSchedule(1e-6, 1.0));
  EXPECT_THROW(OutputSchedule(1e-6, 1.00001), InputError);
  try {
    OutputSchedule(1e-300, 1.0);
    FAIL() << "an interval of 1e-300 s was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("1e+300 outputs"));
  }
  // Below the end time's round-off: k * interval no longer tells outputs apart.
  EXPECT_THROW(OutputSchedule(1e3 * 2.2e-16, 1e3), InputError);
  EXPECT_EQ(output_interval_problem(0.0, 1e9), "");
  EXPECT_EQ(output_interval_problem(2.0, 1.0), "");
}

TEST(OutputSchedule, CaseFilesAreRefusedAtTheIntervalsKeyAndLine) {
  const auto document =
      config::Document::load_string("kind: x_case\noutput:\n  every: 1.0e-300\n", "case.yaml");
  const config::Node every = document.root()["output"]["every"];
  try {
    check_output_interval(every, 10.0);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("case.yaml:3:"));
    EXPECT_THAT(e.what(), HasSubstr("key 'output.every'"));
    EXPECT_THAT(e.what(), HasSubstr("more than 1e+06"));
  }
  EXPECT_NO_THROW(check_output_interval(every, 1e-295));
}

}  // namespace
}  // namespace cosim
