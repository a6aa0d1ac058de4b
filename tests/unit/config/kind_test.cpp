#include "cosim/config/kind.hpp"

#include <gtest/gtest.h>

#include "cosim/config/document.hpp"
#include "input_error.hpp"

namespace cosim::config {
namespace {

using cosim::testing::input_error_from;

Node root_of(const std::string& text) {
  return Document::load_string(text, "case.yaml").root();
}

TEST(ConfigExpectKind, AcceptsTheExpectedKind) {
  EXPECT_NO_THROW(expect_kind(root_of("kind: job\nname: a\n"), "job"));
}

TEST(ConfigExpectKind, WrongKindSaysWhatTheFileIsAndWhatWasExpected) {
  const InputError error =
      input_error_from([] { expect_kind(root_of("name: a\nkind: mpm_case\n"), "job"); });
  EXPECT_STREQ(error.what(),
               "case.yaml:2:7: key 'kind': this is a 'mpm_case' file, but a 'job' file is "
               "expected here");
}

TEST(ConfigExpectKind, MissingKindIsLocatedAtTheTopMapping) {
  const InputError error = input_error_from([] { expect_kind(root_of("name: a\n"), "job"); });
  EXPECT_EQ(error.where().line, 1);
  EXPECT_EQ(error.where().column, 1);
  EXPECT_EQ(error.key_path(), "kind");
  EXPECT_NE(std::string(error.what()).find("missing 'kind: job'"), std::string::npos);
}

TEST(ConfigExpectKind, NonMappingFileIsRefused) {
  const InputError error = input_error_from([] { expect_kind(root_of("- a\n- b\n"), "job"); });
  EXPECT_NE(std::string(error.what()).find("expected a mapping that starts with 'kind: job'"),
            std::string::npos);
}

TEST(ConfigExpectKind, KindMustBeAName) {
  const InputError error = input_error_from([] { expect_kind(root_of("kind: [job]\n"), "job"); });
  EXPECT_EQ(error.where().column, 7);
}

}  // namespace
}  // namespace cosim::config
