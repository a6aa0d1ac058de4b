#include "openfoam/case/existing_case.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"
#include "openfoam/case/generated_case.hpp"
#include "replaced_text.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace openfoam {
namespace {

namespace fs = std::filesystem;

// A complete case (the generated one) that each test then breaks.
void write_case(const fs::path& dir) {
  GeneratedCase g;
  g.upper = {1.0, 1.0, 0.1};
  g.cells = {4, 4, 1};
  g.water = {1000.0, 1e-3};
  g.air = {1.0, 1.8e-5};
  write_generated_case(g, dir);
}

std::string error_of(const fs::path& dir) {
  try {
    check_existing_case(dir);
  } catch (const cosim::InputError& e) {
    EXPECT_EQ(e.code(), cosim::ExitCode::bad_input);
    return e.what();
  }
  return "no error";
}

void replace_in(const fs::path& file, const std::string& from, const std::string& to) {
  cosim::testing::write_text(file,
                             cosim::testing::replaced(cosim::testing::read_text(file), from, to));
}

TEST(OpenFoamExistingCase, ACompleteCasePasses) {
  cosim::testing::ScratchDirectory dir;
  write_case(dir.path());
  EXPECT_EQ(error_of(dir.path()), "no error");
}

TEST(OpenFoamExistingCase, AMissingSolverEntryIsNamedWithItsFile) {
  cosim::testing::ScratchDirectory dir;
  write_case(dir.path());
  replace_in(dir / "system/fvSolution", "\"pcorr.*\"", "\"qcorr.*\"");
  const std::string message = error_of(dir.path());
  EXPECT_NE(message.find("system/fvSolution"), std::string::npos) << message;
  EXPECT_NE(message.find("pcorr"), std::string::npos) << message;
}

TEST(OpenFoamExistingCase, ACommentedOutEntryDoesNotCount) {
  cosim::testing::ScratchDirectory dir;
  write_case(dir.path());
  replace_in(dir / "system/fvSchemes", "div(phi,alpha) Gauss vanLeer;",
             "// div(phi,alpha) Gauss vanLeer;");
  const std::string message = error_of(dir.path());
  EXPECT_NE(message.find("system/fvSchemes"), std::string::npos) << message;
  EXPECT_NE(message.find("div(phi,alpha)"), std::string::npos) << message;
}

TEST(OpenFoamExistingCase, AMissingInitialFieldOrMeshIsNamed) {
  cosim::testing::ScratchDirectory dir;
  write_case(dir.path());
  fs::remove(dir / "0/p_rgh");
  EXPECT_NE(error_of(dir.path()).find("0/p_rgh"), std::string::npos);
  write_case(dir.path());
  fs::remove(dir / "system/blockMeshDict");
  EXPECT_NE(error_of(dir.path()).find("blockMeshDict"), std::string::npos);
}

TEST(OpenFoamExistingCase, ACopyHasTheThreeDirectories) {
  cosim::testing::ScratchDirectory dir;
  write_case(dir / "user");
  copy_existing_case(dir / "user", dir / "run");
  EXPECT_EQ(error_of(dir / "run"), "no error");
}

}  // namespace
}  // namespace openfoam
