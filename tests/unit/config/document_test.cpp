#include "cosim/config/document.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "input_error.hpp"

namespace cosim::config {
namespace {

using testing::input_error_from;
using testing::yaml_text;

namespace fs = std::filesystem;

class ConfigDocumentFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cosim_config_test_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "jobs");
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const fs::path& relative, const std::string& text) const {
    const fs::path file = dir_ / relative;
    std::ofstream(file) << text;
    return file;
  }

  fs::path dir_;
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

}  // namespace
}  // namespace cosim::config
