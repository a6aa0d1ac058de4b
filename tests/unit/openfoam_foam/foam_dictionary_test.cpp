#include "openfoam/foam/foam_dictionary.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"

namespace openfoam {
namespace {

// The values foamDictionary prints for the entries of a user's case.
TEST(OpenFoamDictionaryValue, ANumberIsTheValuesLastToken) {
  EXPECT_EQ(scalar_value("1000", "transportProperties", "water/rho"), 1000.0);
  EXPECT_EQ(scalar_value("[1 -3 0 0 0 0 0] 998", "transportProperties", "water/rho"), 998.0);
  EXPECT_EQ(
      scalar_value("nu [0 2 -1 0 0 0 0] 1.002004008016032e-06", "transportProperties", "water/nu"),
      1.002004008016032e-06);
}

TEST(OpenFoamDictionaryValue, AVectorIsTheValuesLastThreeNumbers) {
  EXPECT_EQ(vector_value("(0 -9.81 0)", "g", "value"), (Vector3{0.0, -9.81, 0.0}));
  EXPECT_EQ(vector_value("[0 1 -2 0 0 0 0] ( 0.5 -9.81 0 )", "g", "value"),
            (Vector3{0.5, -9.81, 0.0}));
}

TEST(OpenFoamDictionaryValue, AValueWithoutItsNumberNamesFileAndEntry) {
  for (const char* value : {"Newtonian", "[1 -3 0 0 0 0 0]", ""}) {
    try {
      (void)scalar_value(value, "constant/transportProperties", "water/rho");
      FAIL() << value;
    } catch (const cosim::InputError& e) {
      EXPECT_EQ(e.code(), cosim::ExitCode::bad_input);
      const std::string message = e.what();
      EXPECT_NE(message.find("constant/transportProperties"), std::string::npos) << message;
      EXPECT_NE(message.find("water/rho"), std::string::npos) << message;
    }
  }
  EXPECT_THROW((void)vector_value("(0 -9.81)", "g", "value"), cosim::InputError);
}

}  // namespace
}  // namespace openfoam
