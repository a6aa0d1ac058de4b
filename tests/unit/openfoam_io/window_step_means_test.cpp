#include "openfoam/io/window_step_means.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "openfoam/foam/field_file.hpp"
#include "scratch_directory.hpp"

namespace openfoam {
namespace {

namespace fs = std::filesystem;

void write_step(const fs::path& case_dir, const std::string& time, const std::vector<double>& p,
                const std::vector<double>& trans) {
  fs::create_directories(case_dir / time);
  const std::string patches = "    \".*\" { type zeroGradient; }";
  write_vol_field(case_dir / time / "p", time,
                  {FieldType::scalar, "[1 -1 -2 0 0 0 0]", p, patches});
  write_vol_field(case_dir / time / "kinematicCloud:UTrans", time,
                  {FieldType::vector, "[1 1 -1 0 0 0 0]", trans, patches});
}

// A window of two steps after a restart, the pressure alternating ahead of
// the subaerial slide's grains (205 then 1480 Pa) and the drag with it: the
// soil gets the means.
TEST(WindowStepMeans, ThePressureAndTheCloudsMomentumAreTheMeansOfTheWindowsSteps) {
  cosim::testing::ScratchDirectory dir;
  write_step(dir.path(), "0.6005", {205.0, 100.0}, {1.4e-4, -1.2e-4, 0.0, 0.0, 0.0, 0.0});
  const CaseLayout layout(dir.path(), 1, 2);
  FoamFields end;
  end.p = {1480.0, 100.0};
  end.cloud_momentum = {-4.2e-5, 2.0e-5, 0.0, 1.0};
  const std::vector<std::string> steps{"0.6005"};
  average_over_window_steps(layout, steps, end, 2);
  EXPECT_EQ(end.p, (std::vector<double>{842.5, 100.0}));
  ASSERT_EQ(end.cloud_momentum.size(), 4u);
  EXPECT_DOUBLE_EQ(end.cloud_momentum[0], 0.5 * (1.4e-4 - 4.2e-5));
  EXPECT_DOUBLE_EQ(end.cloud_momentum[1], 0.5 * (-1.2e-4 + 2.0e-5));
  EXPECT_DOUBLE_EQ(end.cloud_momentum[3], 0.5);
}

TEST(WindowStepMeans, AOneStepWindowKeepsItsEndsFields) {
  cosim::testing::ScratchDirectory dir;
  const CaseLayout layout(dir.path(), 1, 1);
  FoamFields end;
  end.p = {42.0};
  end.cloud_momentum = {1.0, 2.0};
  average_over_window_steps(layout, {}, end, 2);
  EXPECT_EQ(end.p, std::vector<double>{42.0});
  EXPECT_EQ(end.cloud_momentum, (std::vector<double>{1.0, 2.0}));
}

}  // namespace
}  // namespace openfoam
