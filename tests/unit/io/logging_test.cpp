#include "cosim/io/logging.hpp"

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include "cosim/error.hpp"
#include "cosim/io/tail_lines.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace cosim {
namespace {

using testing::read_text;
using testing::ScratchDirectory;

TEST(Logging, FileSinkKeepsInfoEvenWhenConsoleIsQuietAndFlushesEveryLine) {
  ScratchDirectory dir;
  const auto logger = init_logging(dir / "run", "swe_fluid", Verbosity::quiet);
  EXPECT_EQ(spdlog::default_logger(), logger);
  spdlog::info("window {} done", 7);
  spdlog::debug("not recorded at quiet");
  spdlog::warn("CFL {:.2f}", 0.95);
  const auto lines = tail_lines(dir / "run" / "log.txt", 10);  // read without closing the logger
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("] [swe_fluid] [info] window 7 done"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("[warning] CFL 0.95"), std::string::npos) << lines[1];
  EXPECT_EQ(lines[0].front(), '[');
}

TEST(Logging, SecondCallReplacesTheDefaultLogger) {
  ScratchDirectory dir;
  init_logging(dir / "first", "cosim", Verbosity::verbose);
  spdlog::debug("debug kept at verbose");
  init_logging(dir / "second", "cosim", Verbosity::normal);
  spdlog::info("only in the second");
  EXPECT_EQ(read_text(dir / "first" / "log.txt").find("only in the second"), std::string::npos);
  EXPECT_NE(read_text(dir / "first" / "log.txt").find("debug kept at verbose"), std::string::npos);
  EXPECT_NE(read_text(dir / "second" / "log.txt").find("only in the second"), std::string::npos);
  spdlog::set_default_logger(std::make_shared<spdlog::logger>("io_test_after"));
}

TEST(Logging, ParsesVerbosityNames) {
  EXPECT_EQ(parse_verbosity("quiet"), Verbosity::quiet);
  EXPECT_EQ(parse_verbosity("trace"), Verbosity::trace);
  EXPECT_THROW(parse_verbosity("loud"), InputError);
}

}  // namespace
}  // namespace cosim
