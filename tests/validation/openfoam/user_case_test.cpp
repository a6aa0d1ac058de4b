// A user's own OpenFOAM case directory in a coupled job
// (configs/openfoam_coupled/darcy_user_case: an interFoam case written by
// hand, with dimensioned transport entries, its own patch names, no cloud
// dictionaries) in place of the case the adapter generates for the same
// Darcy column (configs/openfoam_coupled/darcy: phi_s = 0.6, dp = 0.5 atm).
// The adapter reads the fluids from its transportProperties and its plane
// from checkMesh, completes the copy for MPPICInterFoam and declares the
// cells as a cell cloud, which the coupler maps to the MPM's grid and to
// itself (the momentum exchange's mesh). Over the first 6 windows the
// gauges of the two runs agree to 1e-9 (they are the same computation).
//
// Needs OpenFOAM (openfoam_test_main.cpp).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

const fs::path configs = fs::path(COSIM_SOURCE_DIR) / "configs/openfoam_coupled";

void run_job(const fs::path& job) {
  const ProcessResult r = run({binary("cosim").string(), "run", job.string(), "--output",
                               (job.parent_path() / "run").string()},
                              std::chrono::seconds(300));
  ASSERT_EQ(r.exit_code, 0) << r.output;
}

TEST(OpenFoamUserCase, AUsersCaseDirectoryGivesTheGeneratedCasesFlow) {
  const fs::path dir = fresh_directory("openfoam_user_case");
  const auto shortened = [](const fs::path& job) {
    return replaced(read_text(job), "end_time: 0.08", "end_time: 0.03");
  };
  const fs::path generated = dir / "generated";
  fs::create_directories(generated);
  write_text(generated / "job.yaml", shortened(configs / "darcy" / "job.yaml"));
  for (const char* f : {"column.yaml", "water.yaml"})
    write_text(generated / f, read_text(configs / "darcy" / f));
  const fs::path user = dir / "user";
  fs::create_directories(user);
  fs::copy(configs / "darcy_user_case" / "case", user / "case", fs::copy_options::recursive);
  write_text(user / "water.yaml", read_text(configs / "darcy_user_case" / "water.yaml"));
  write_text(user / "job.yaml",
             replaced(shortened(configs / "darcy_user_case" / "job.yaml"), "../darcy/column.yaml",
                      (configs / "darcy" / "column.yaml").string()));
  run_job(generated / "job.yaml");
  run_job(user / "job.yaml");

  const auto expected = read_csv(generated / "run" / "water" / "gauges.csv");
  const auto got = read_csv(user / "run" / "water" / "gauges.csv");
  ASSERT_EQ(got.size(), expected.size());
  ASSERT_GE(got.size(), 6u);
  double largest = 0.0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].size(), expected[i].size());
    for (std::size_t k = 0; k < got[i].size(); ++k) {
      largest = std::max(
          largest, std::abs(got[i][k] - expected[i][k]) / std::max(1.0, std::abs(expected[i][k])));
    }
  }
  fmt::print(
      "user's case against the generated case over {} gauge rows: largest difference {:.1e} "
      "(tolerance 1e-9); column velocity {:.5f} vs {:.5f} m/s at t = {} s\n",
      got.size(), largest, got.back()[3], expected.back()[3], got.back()[0]);
  EXPECT_LE(largest, 1e-9);

  const auto summary = nlohmann::json::parse(read_text(user / "run" / "water" / "summary.json"));
  EXPECT_FALSE(summary["case"]["generated"].get<bool>());
  EXPECT_EQ(summary["case"]["dimension"].get<int>(), 2);
  EXPECT_DOUBLE_EQ(summary["case"]["water_density_kg/m^3"].get<double>(), 998.0);
  EXPECT_NEAR(summary["case"]["water_viscosity_Pa_s"].get<double>(), 1e-3, 1e-15);
  // The water's mass per unit depth: the free metre and the column's pores.
  const auto& water = summary["conserved"]["mass_water"];
  EXPECT_NEAR(water["start"].get<double>(), 998.0 * 0.1 * (1.0 + 0.4), 1e-9);
  EXPECT_LE(std::abs(water["relative_change"].get<double>()), 1e-9);
  // The copy was completed for MPPICInterFoam.
  const fs::path copy = user / "run" / "water" / "case";
  EXPECT_TRUE(fs::exists(copy / "constant" / "kinematicCloudProperties"));
  EXPECT_NE(
      read_text(copy / "system" / "fvSchemes").find("div((((alphac*rho)*nuEff)*dev2(T(grad(U)))))"),
      std::string::npos);
}

}  // namespace
}  // namespace cosim::testing
