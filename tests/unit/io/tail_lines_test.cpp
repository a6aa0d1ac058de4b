#include "cosim/io/tail_lines.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace cosim {
namespace {

using testing::ScratchDirectory;
using testing::write_text;
using Lines = std::vector<std::string>;

TEST(TailLines, SmallFiles) {
  ScratchDirectory dir;
  const auto path = dir / "log.txt";
  write_text(path, "one\ntwo\nthree\n");
  EXPECT_EQ(tail_lines(path, 2), (Lines{"two", "three"}));
  EXPECT_EQ(tail_lines(path, 10), (Lines{"one", "two", "three"}));
  EXPECT_EQ(tail_lines(path, 0), Lines{});
  write_text(path, "one\r\ntwo\r\nno newline at end");
  EXPECT_EQ(tail_lines(path, 2), (Lines{"two", "no newline at end"}));
  write_text(path, "a\n\nb\n\n");
  EXPECT_EQ(tail_lines(path, 3), (Lines{"", "b", ""}));
  write_text(path, "");
  EXPECT_EQ(tail_lines(path, 3), Lines{});
  EXPECT_EQ(tail_lines(dir / "missing.txt", 3), Lines{});
}

TEST(TailLines, LargeFileReadsAcrossBlocks) {
  ScratchDirectory dir;
  const auto path = dir / "big.log";
  {
    std::ofstream out(path);
    for (int i = 0; i < 200000; ++i) out << "[info] step " << i << " of a long run\n";
  }
  const Lines last = tail_lines(path, 5);
  ASSERT_EQ(last.size(), 5u);
  for (int k = 0; k < 5; ++k)
    EXPECT_EQ(last[k], "[info] step " + std::to_string(199995 + k) + " of a long run");
  const Lines many = tail_lines(path, 3000);  // spans several 16 KiB blocks
  ASSERT_EQ(many.size(), 3000u);
  EXPECT_EQ(many.front(), "[info] step 197000 of a long run");
  const std::string long_line(100000, 'x');
  write_text(path, "first\n" + long_line + "\nlast\n");
  EXPECT_EQ(tail_lines(path, 2), (Lines{long_line, "last"}));
  EXPECT_EQ(tail_lines(path, 3).front(), "first");
}

}  // namespace
}  // namespace cosim
