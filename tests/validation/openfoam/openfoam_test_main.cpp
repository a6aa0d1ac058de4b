// The main of the validations that need OpenFOAM: without it they exit 77,
// which CTest reports as not run (SKIP_RETURN_CODE), printing why.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cosim/error.hpp"
#include "openfoam/foam/installation.hpp"

int main(int argc, char** argv) {
  try {
    openfoam::find_installation(
        {"interFoam", "MPPICInterFoam", "blockMesh", "setFields", "postProcess"});
  } catch (const cosim::Error& e) {
    fmt::print("OpenFOAM is not installed, so this test does not run: {}\n", e.what());
    return 77;
  }
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
