// Particles read from CSV files, and the located errors for bad files.
#include "mpm/geometry/particle_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "cosim/error.hpp"
#include "scratch_directory.hpp"

namespace mpm {
namespace {

class ParticleFileTest : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) const {
    return scratch_.write(name, text).string();
  }

  // The message of the InputError thrown by reading `text` as a Dim-D file.
  template <int Dim>
  std::string error_of(const std::string& text, std::string* path_out = nullptr) {
    const std::string path = write("particles.csv", text);
    if (path_out) *path_out = path;
    try {
      read_particle_file<Dim>(path);
    } catch (const cosim::InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return {};
  }

 private:
  cosim::testing::ScratchDirectory scratch_;
};

TEST_F(ParticleFileTest, Reads2DWithExtraColumnsCommentsAndBlanks) {
  const std::string path = write("p.csv",
                                 "# particles of the slope\n"
                                 " volume, x ,y,porosity\r\n"
                                 "0.0004, 0.01, 0.02, 0.4\n"
                                 "\n"
                                 "# a comment\n"
                                 "1e-4,-1.5e-1,2,0.35\n");
  const auto file = read_particle_file<2>(path);
  ASSERT_EQ(file.particles.size(), 2u);
  EXPECT_EQ(file.particles.positions[0], Vec<2>(0.01, 0.02));
  EXPECT_EQ(file.particles.positions[1], Vec<2>(-0.15, 2.0));
  EXPECT_EQ(file.particles.volumes[1], 1e-4);
  EXPECT_NEAR(file.particles.half_lengths[0].x(), 0.5 * std::sqrt(0.0004), 1e-16);
  EXPECT_NEAR(file.particles.half_lengths[0].y(), 0.01, 1e-16);
  ASSERT_EQ(file.extra_columns.count("porosity"), 1u);
  EXPECT_EQ(file.extra_columns.at("porosity"), (std::vector<double>{0.4, 0.35}));
}

TEST_F(ParticleFileTest, Reads3D) {
  const auto file = read_particle_file<3>(write("p.csv", "x,y,z,volume\n1,2,3,0.008\n"));
  ASSERT_EQ(file.particles.size(), 1u);
  EXPECT_EQ(file.particles.positions[0], Vec<3>(1, 2, 3));
  EXPECT_NEAR(file.particles.half_lengths[0].z(), 0.1, 1e-15);
  EXPECT_TRUE(file.extra_columns.empty());
}

TEST_F(ParticleFileTest, ErrorsNameFileLineAndColumn) {
  std::string path;
  std::string message = error_of<2>("x,y,volume\n0,0,1\n0,abc,1\n", &path);
  EXPECT_NE(message.find(path + ":3:3:"), std::string::npos) << message;
  EXPECT_NE(message.find("'abc'"), std::string::npos) << message;

  message = error_of<2>("x,y,volume\n0,0,1\n\n0,0\n", &path);
  EXPECT_NE(message.find(path + ":4:"), std::string::npos) << message;
  EXPECT_NE(message.find("expected 3 values"), std::string::npos) << message;

  message = error_of<3>("x,y,volume\n0,0,1\n", &path);
  EXPECT_NE(message.find(path + ":1:"), std::string::npos) << message;
  EXPECT_NE(message.find("'z'"), std::string::npos) << message;

  message = error_of<2>("# header next\nx,y,volume\n0,0,1\n1,1,0\n", &path);
  EXPECT_NE(message.find(path + ":4:5:"), std::string::npos) << message;
  EXPECT_NE(message.find("positive"), std::string::npos) << message;

  message = error_of<2>("x,y,volume\n0,0,-2\n");
  EXPECT_NE(message.find(":2:"), std::string::npos) << message;

  message = error_of<2>("x,y,volume,x\n0,0,1,0\n");
  EXPECT_NE(message.find("twice"), std::string::npos) << message;

  message = error_of<2>("x,y,volume\n0,nan,1\n");
  EXPECT_NE(message.find(":2:"), std::string::npos) << message;

  message = error_of<2>("x,y,volume\n0,1 2,1\n");
  EXPECT_NE(message.find(":2:"), std::string::npos) << message;

  message = error_of<2>("x,y,volume\n# nothing\n");
  EXPECT_NE(message.find("no particles"), std::string::npos) << message;

  message = error_of<2>("");
  EXPECT_NE(message.find("header"), std::string::npos) << message;

  EXPECT_THROW(read_particle_file<2>("/nonexistent/particles.csv"), cosim::InputError);
}

}  // namespace
}  // namespace mpm
