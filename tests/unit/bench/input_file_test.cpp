#include "bench/input_file.hpp"

#include <gtest/gtest.h>

#include "cosim/error.hpp"
#include "scratch_directory.hpp"

namespace cosim::bench {
namespace {

using cosim::testing::ScratchDirectory;

Override set(const std::string& key_path, const std::string& yaml) {
  return {"case", key_path, YAML::Load(yaml), {"suite.yaml", 7, 3}};
}

TEST(InputFile, OverridesNestedKeysListItemsAndNewKeys) {
  ScratchDirectory dir;
  InputFile f = InputFile::read(dir.write(
      "case.yaml",
      "kind: mpm_case\ngrid: {cells: [10, 5]}\nbodies:\n  - {name: a, porous: {porosity: 0.4}}\n"));
  f.apply(set("grid.cells", "[20, 10]"));
  f.apply(set("bodies.0.porous.porosity", "0.3"));
  f.apply(set("output.every", "0.5"));
  EXPECT_EQ(scalar_at(f.root(), "grid.cells.0"), "20");
  EXPECT_EQ(scalar_at(f.root(), "bodies.0.porous.porosity"), "0.3");
  EXPECT_EQ(scalar_at(f.root(), "output.every"), "0.5");
  EXPECT_EQ(scalar_at(f.root(), "bodies.0.name"), "a");
  EXPECT_EQ(scalar_at(f.root(), "bodies.3.name", "none"), "none");
}

TEST(InputFile, RefusesAnIndexBeyondAListAtTheOverridesLocation) {
  ScratchDirectory dir;
  InputFile f = InputFile::read(dir.write("case.yaml", "bodies:\n  - {name: a}\n"));
  try {
    f.apply(set("bodies.2.name", "b"));
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("suite.yaml:7:3"), std::string::npos) << m;
    EXPECT_NE(m.find("a list of 1 items"), std::string::npos) << m;
  }
  EXPECT_THROW(f.apply(set("bodies.0.name.first", "x")), InputError);
}

TEST(InputFile, MakesRelativePathsAbsoluteAndRemembersTheFilesTheyName) {
  ScratchDirectory dir;
  dir.write("data/history.csv", "time [s],vx [m/s]\n0,0\n");
  InputFile f = InputFile::read(dir.write(
      "case.yaml", "name: data\nrigid: {velocity_history: data/history.csv}\nother: not_a_file\n"));
  const auto absolute = std::filesystem::weakly_canonical(dir.path() / "data/history.csv");
  EXPECT_EQ(scalar_at(f.root(), "rigid.velocity_history"), absolute.string());
  EXPECT_EQ(scalar_at(f.root(), "name"), "data");  // a name, although a directory is called so
  EXPECT_EQ(scalar_at(f.root(), "other"), "not_a_file");
  ASSERT_EQ(f.referenced_files().size(), 1u);
  EXPECT_EQ(*f.referenced_files().begin(), absolute);
}

TEST(InputFile, WritesWhatItHolds) {
  ScratchDirectory dir;
  InputFile f = InputFile::read(dir.write("case.yaml", "kind: swe_case\nmesh: {cells: 10}\n"));
  f.apply(set("mesh.cells", "40"));
  f.write(dir.path() / "copy.yaml");
  const InputFile back = InputFile::read(dir.path() / "copy.yaml");
  EXPECT_EQ(scalar_at(back.root(), "mesh.cells"), "40");
  EXPECT_EQ(scalar_at(back.root(), "kind"), "swe_case");
}

}  // namespace
}  // namespace cosim::bench
