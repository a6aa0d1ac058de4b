#include "cosim/config/document.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "input_error.hpp"
#include "scratch_directory.hpp"
#include "yaml_text.hpp"

namespace cosim::config {
namespace {

using cosim::testing::input_error_from;
using testing::column_of;
using testing::yaml_text;

namespace fs = std::filesystem;

class ConfigDocumentFile : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(dir_ / "jobs"); }

  fs::path write(const fs::path& relative, const std::string& text) const {
    return scratch_.write(relative, text);
  }

  cosim::testing::ScratchDirectory scratch_;
  fs::path dir_ = scratch_.path();
};

TEST_F(ConfigDocumentFile, LoadsAFileAndKeepsItsPathAndText) {
  const std::string text = "kind: job\nend_time: 5.0\n";
  const fs::path file = write("jobs/job.yaml", text);
  const Document document = Document::load_file(file);
  EXPECT_EQ(document.path(), file);
  EXPECT_EQ(document.directory(), dir_ / "jobs");
  EXPECT_EQ(document.text(), text);
  EXPECT_DOUBLE_EQ(document.root()["end_time"].as<double>(), 5.0);
}

TEST_F(ConfigDocumentFile, RelativePathsResolveFromTheFilesOwnDirectory) {
  const fs::path file =
      write("jobs/job.yaml", yaml_text({"kind: job", "soil: mpm/clay.yaml", "up: ../meshes/a.msh",
                                        "absolute: /opt/data/b.yaml"}));
  const Node root = Document::load_file(file).root();
  EXPECT_EQ(root["soil"].as_path(), dir_ / "jobs" / "mpm" / "clay.yaml");
  EXPECT_EQ(root["up"].as_path(), dir_ / "meshes" / "a.msh");
  EXPECT_EQ(root["absolute"].as_path(), fs::path("/opt/data/b.yaml"));
}

TEST_F(ConfigDocumentFile, RelativePathsOfAFileGivenRelativelyStillResolveFromIt) {
  write("jobs/job.yaml", "config: mpm/clay.yaml\n");
  const fs::path before = fs::current_path();
  fs::current_path(dir_);
  const Document document = Document::load_file("jobs/job.yaml");
  fs::current_path(before);
  EXPECT_EQ(document.root()["config"].as_path(), dir_ / "jobs" / "mpm" / "clay.yaml");
}

TEST_F(ConfigDocumentFile, MissingFileNamesTheFile) {
  const fs::path file = dir_ / "jobs" / "absent.yaml";
  const InputError error = input_error_from([&] { Document::load_file(file); });
  EXPECT_EQ(error.where().file, file.string());
  EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos);
  EXPECT_NE(std::string(error.what()).find("file not found"), std::string::npos);
  EXPECT_EQ(error.code(), ExitCode::bad_input);
}

TEST_F(ConfigDocumentFile, DirectoryIsRefused) {
  const InputError error = input_error_from([&] { Document::load_file(dir_ / "jobs"); });
  EXPECT_NE(std::string(error.what()).find("is a directory"), std::string::npos);
}

TEST(ConfigDocument, UnclosedFlowSequenceIsASyntaxErrorWithLineAndColumn) {
  const InputError error = input_error_from([] {
    Document::load_string(yaml_text({"kind: job", "gravity: [0, -9.81", "window: 1"}), "job.yaml");
  });
  EXPECT_EQ(error.where().file, "job.yaml");
  EXPECT_EQ(error.where().line, 3);
  EXPECT_GT(error.where().column, 0);
  EXPECT_NE(std::string(error.what()).find("YAML syntax error"), std::string::npos);
  EXPECT_NE(std::string(error.what()).find("job.yaml:3:"), std::string::npos);
}

TEST(ConfigDocument, TabIndentationIsASyntaxErrorThatNamesTheTab) {
  const InputError error = input_error_from([] {
    Document::load_string(yaml_text({"kind: job", "output:", "\tevery: 0.05"}), "job.yaml");
  });
  EXPECT_EQ(error.where().line, 3);
  EXPECT_NE(std::string(error.what()).find("YAML syntax error"), std::string::npos);
  EXPECT_NE(std::string(error.what()).find("line 3 is indented with a tab"), std::string::npos);
}

TEST(ConfigDocument, BadIndentationIsASyntaxError) {
  const InputError error = input_error_from([] {
    Document::load_string(
        yaml_text({"participants:", "  soil:", "    config: a.yaml", "   executable: mpm_solver"}),
        "job.yaml");
  });
  EXPECT_EQ(error.where().line, 4);
  EXPECT_NE(std::string(error.what()).find("YAML syntax error"), std::string::npos);
}

TEST(ConfigDocument, DuplicateKeyIsLocatedAtItsSecondOccurrence) {
  const InputError error = input_error_from([] {
    Document::load_string(yaml_text({"kind: job", "participants:", "  soil: {config: a.yaml}",
                                     "  soil: {config: b.yaml}"}),
                          "job.yaml");
  });
  EXPECT_EQ(error.where().line, 4);
  EXPECT_EQ(error.where().column, 3);
  EXPECT_EQ(error.key_path(), "participants.soil");
  EXPECT_NE(std::string(error.what()).find("first given at line 3"), std::string::npos);
}

TEST(ConfigDocument, DuplicateKeyInsideAListItemNamesTheItem) {
  const InputError error = input_error_from([] {
    Document::load_string(yaml_text({"exchange:", "  - {from: a, to: b, from: c}"}), "job.yaml");
  });
  EXPECT_EQ(error.key_path(), "exchange[0].from");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 22);
}

TEST(ConfigDocument, EmptyFileIsRefused) {
  for (const char* text : {"", "# only a comment\n", "~\n"}) {
    const InputError error = input_error_from([&] { Document::load_string(text, "empty.yaml"); });
    EXPECT_NE(std::string(error.what()).find("empty.yaml: the file is empty"), std::string::npos);
  }
}

TEST(ConfigDocument, SecondYamlDocumentIsRefused) {
  const InputError error = input_error_from([] {
    Document::load_string(yaml_text({"kind: job", "---", "kind: job"}), "two.yaml");
  });
  EXPECT_EQ(error.where().line, 3);
  EXPECT_NE(std::string(error.what()).find("second YAML document"), std::string::npos);
}

TEST(ConfigDocument, ComplexKeyIsRefused) {
  const InputError error =
      input_error_from([] { Document::load_string("? [a, b]\n: 1\n", "job.yaml"); });
  EXPECT_EQ(error.where().line, 1);
  EXPECT_NE(std::string(error.what()).find("plain name"), std::string::npos);
}

// yaml-cpp 0.7 leaves a stray ',' unread and reads the same empty document
// before it again, without end (jbeder/yaml-cpp#1040).
TEST(ConfigDocument, StrayCommaIsASyntaxErrorNotAnEndlessLoop) {
  for (const std::string text : {",", "# comment\n, kind: job\n"}) {
    const InputError error = input_error_from([&] { Document::load_string(text, "job.yaml"); });
    EXPECT_NE(std::string(error.what()).find("YAML syntax error: unexpected ','"),
              std::string::npos);
  }
}

// Aliases: yaml-cpp makes an alias share its anchor's node, so an alias
// inside that node makes it contain itself (a cycle), and each alias counts
// its anchor's nodes again for every walk over the document.

TEST(ConfigDocument, AliasInsideItsOwnListIsRefusedAtTheAlias) {
  const std::string line = "gravity: &a [0.0, *a]";
  const InputError error = input_error_from([&] {
    Document::load_string(yaml_text({"kind: job", line}), "job.yaml");
  });
  EXPECT_EQ(error.code(), ExitCode::bad_input);
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, column_of(line, "*a"));
  EXPECT_EQ(error.key_path(), "gravity[1]");
  const std::string what = error.what();
  EXPECT_NE(what.find("alias '*a' lies inside the node anchored as '&a' at line 2"),
            std::string::npos);
}

TEST(ConfigDocument, AliasInsideItsOwnMappingIsRefusedAtTheAliasLine) {
  const InputError error = input_error_from([] {
    Document::load_string(yaml_text({"kind: job", "output: &out", "  every: 0.1", "  again: *out"}),
                          "job.yaml");
  });
  EXPECT_EQ(error.where().line, 4);
  EXPECT_EQ(error.key_path(), "output.again");
  EXPECT_NE(std::string(error.what()).find("anchored as '&out' at line"), std::string::npos);
}

TEST(ConfigDocument, MappingThatMergesItselfIsRefused) {
  const std::string line = "output: &out {<<: *out, every: 0.1}";
  const InputError error = input_error_from([&] {
    Document::load_string(yaml_text({"kind: job", line}), "job.yaml");
  });
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, column_of(line, "*out"));
  EXPECT_EQ(error.key_path(), "output.<<");
}

TEST(ConfigDocument, CycleThroughANestedAnchorIsRefused) {
  const InputError error = input_error_from([] {
    Document::load_string(yaml_text({"a: &a", "  b: &b", "    c: [1, *b]", "  d: *a"}), "job.yaml");
  });
  EXPECT_EQ(error.where().line, 3);
  EXPECT_EQ(error.key_path(), "a.b.c[1]");
  EXPECT_NE(std::string(error.what()).find("alias '*b'"), std::string::npos);
}

// Nine levels of ten aliases each, 10^9 nodes when expanded (the "billion
// laughs"): as lists, or as mappings that also merge the level before.
std::string alias_bomb(bool merging) {
  std::string text =
      merging ? "a0: &a0 {x0: lol, x1: lol, x2: lol}\n" : "a0: &a0 [lol, lol, lol]\n";
  for (int level = 1; level < 9; ++level) {
    std::string items;
    for (int i = 0; i < 10; ++i) {
      items +=
          fmt::format("{}{}*a{}", i ? ", " : "", merging ? fmt::format("x{}: ", i) : "", level - 1);
    }
    text += merging ? fmt::format("a{0}: &a{0} {{<<: *a{1}, {2}}}\n", level, level - 1, items)
                    : fmt::format("a{0}: &a{0} [{1}]\n", level, items);
  }
  return text;
}

TEST(ConfigDocument, AliasBombIsRefusedNamingTheLimitAndTheSize) {
  const InputError error =
      input_error_from([] { Document::load_string(alias_bomb(false), "bomb.yaml"); });
  EXPECT_EQ(error.code(), ExitCode::bad_input);
  EXPECT_GT(error.where().line, 1);
  const std::string what = error.what();
  EXPECT_NE(
      what.find(fmt::format("holds more than {} nodes (the limit)", Document::max_expanded_nodes)),
      std::string::npos);
  EXPECT_NE(what.find("bringing it to"), std::string::npos);
}

TEST(ConfigDocument, MergeKeysThatCopyAnAliasBombAreRefused) {
  const InputError error =
      input_error_from([] { Document::load_string(alias_bomb(true), "bomb.yaml"); });
  EXPECT_NE(std::string(error.what()).find("nodes (the limit)"), std::string::npos);
}

TEST(ConfigDocument, ListsNestedBeyondTheDepthLimitAreRefused) {
  for (const int depth : {Document::max_depth + 1, 100000}) {
    const std::string text = "kind: job\nx: " + std::string(depth, '[') + std::string(depth, ']');
    const InputError error = input_error_from([&] { Document::load_string(text, "deep.yaml"); });
    EXPECT_EQ(error.where().line, 2);
    EXPECT_NE(
        std::string(error.what()).find(fmt::format("more than {} levels", Document::max_depth)),
        std::string::npos);
  }
}

TEST(ConfigDocument, MappingsNestedBeyondTheDepthLimitAreRefused) {
  std::string flow, block;
  for (int level = 0; level < 100000; ++level) flow += "{a: ";
  flow += "1" + std::string(100000, '}');
  for (int level = 0; level <= Document::max_depth; ++level)
    block += std::string(static_cast<std::size_t>(level), ' ') + "a:\n";
  for (const std::string& text : {flow, block}) {
    const InputError error = input_error_from([&] { Document::load_string(text, "deep.yaml"); });
    EXPECT_NE(std::string(error.what()).find("levels"), std::string::npos);
  }
}

TEST(ConfigDocument, NestingThroughAliasesCountsTheAnchorsDepth) {
  // Each anchor nests the one before 40 levels deeper.
  std::string text = "a0: &a0 " + std::string(40, '[') + "1" + std::string(40, ']') + "\n";
  for (int i = 1; i < 5; ++i) {
    text += fmt::format("a{0}: &a{0} {1}*a{2}{3}\n", i, std::string(40, '['), i - 1,
                        std::string(40, ']'));
  }
  const InputError error = input_error_from([&] { Document::load_string(text, "deep.yaml"); });
  EXPECT_EQ(error.where().line, 3);
  EXPECT_NE(std::string(error.what()).find("alias '*a1'"), std::string::npos);
}

// A document of exactly `nodes` nodes with its aliases expanded: a list of
// 999 scalars under an anchor, a list of aliases to it (each adds the 1000
// nodes of the list), and a list of scalars for the rest.
std::string document_of(std::uint64_t nodes) {
  const std::uint64_t anchored = 3 + 999;  // the root, key `a`, its list and scalars
  const std::uint64_t aliases = (nodes - anchored) / 1000 - 1;
  const std::uint64_t rest = nodes - anchored - 2 - aliases * 1000 - 2;  // keys `b`, `c`, lists
  const auto list = [](std::uint64_t n, const std::string& item) {
    std::string text = "[";
    for (std::uint64_t i = 0; i < n; ++i) text += (i ? ", " : "") + item;
    return text + "]\n";
  };
  return "a: &a " + list(999, "0") + "b: " + list(aliases, "*a") + "c: " + list(rest, "0");
}

TEST(ConfigDocument, DocumentsAtTheLimitsLoad) {
  const std::uint64_t limit = Document::max_expanded_nodes;
  EXPECT_TRUE(Document::load_string(document_of(limit), "large.yaml").root()["c"].is_sequence());
  const InputError error =
      input_error_from([&] { Document::load_string(document_of(limit + 1), "large.yaml"); });
  EXPECT_EQ(error.where().line, 3);
  EXPECT_EQ(error.key_path().substr(0, 2), "c[");
  EXPECT_NE(std::string(error.what()).find(fmt::format("holds more than {} nodes", limit)),
            std::string::npos);

  // The root mapping, max_depth - 2 lists and a scalar: max_depth levels.
  const auto lists = static_cast<std::size_t>(Document::max_depth - 2);
  const std::string deep = "x: " + std::string(lists, '[') + "1" + std::string(lists, ']');
  EXPECT_TRUE(Document::load_string(deep, "deep.yaml").root()["x"].is_sequence());
  const std::string deeper = "x: [" + deep.substr(3) + "]";
  const InputError too_deep = input_error_from([&] { Document::load_string(deeper, "deep.yaml"); });
  EXPECT_NE(std::string(too_deep.what()).find("levels"), std::string::npos);
}

TEST(ConfigDocument, AnchorsUsedManyTimesStillLoad) {
  const Document document = Document::load_string(
      yaml_text({"base: &base {every: 0.1, format: hdf5}", "runs:", "  - {output: *base}",
                 "  - {output: *base}", "  - output: {<<: *base, every: 0.2}"}),
      "job.yaml");
  const auto runs = document.root()["runs"].items();
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_DOUBLE_EQ(runs[1]["output"]["every"].as<double>(), 0.1);
  EXPECT_DOUBLE_EQ(runs[2]["output"]["every"].as<double>(), 0.2);
  EXPECT_EQ(runs[2]["output"]["format"].as<std::string>(), "hdf5");
}

TEST(ConfigDocument, MergeKeysCopyWhatTheMappingLacksFirstSourceWinning) {
  const Document document =
      Document::load_string(yaml_text({"a: &a {x: 1, y: 1, z: 1}", "b: &b {<<: *a, y: 2}",
                                       "c: &c {w: 3, x: 3}", "d: {<<: [*c, *b], z: 4}"}),
                            "job.yaml");
  const Node d = document.root()["d"];
  EXPECT_FALSE(d.has("<<"));
  EXPECT_EQ(d.size(), 4u);
  EXPECT_EQ(d["w"].as<int>(), 3);
  EXPECT_EQ(d["x"].as<int>(), 3) << "the first source of the list wins";
  EXPECT_EQ(d["y"].as<int>(), 2) << "b's own key, merged through the chain";
  EXPECT_EQ(d["z"].as<int>(), 4) << "the mapping's own key";
  EXPECT_EQ(document.root()["b"]["x"].as<int>(), 1);
}

// Merging a value (not a mapping) would silently merge nothing.
TEST(ConfigDocument, AMergeKeyOfAValueIsRefusedAtIt) {
  for (const char* merged : {"<<: 1", "<<: [{x: 1}, 2]", "<<: [a, b]"}) {
    try {
      Document::load_string(yaml_text({"a: 0", std::string("b: {") + merged + "}"}), "job.yaml");
      FAIL() << merged << " was accepted";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("job.yaml:2:")) << merged;
      EXPECT_THAT(e.what(), ::testing::HasSubstr("merge key takes a mapping")) << merged;
    }
  }
}

}  // namespace
}  // namespace cosim::config
