// Every YAML file shipped under configs/ loads: jobs through the coupler's
// loader (schema and cross-references), MPM, shallow-water, ICE and OpenFOAM cases through
// their solvers' loaders. A key renamed in a schema, or an example left
// behind by a change, fails here rather than in a user's first run.
// `kind: test_participant` files are read by the test participant, which
// the demo jobs run in cosim_run_test.
#include <gtest/gtest.h>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <string>

#include "cosim/job/job.hpp"
#include "ice/case/load_case.hpp"
#include "mpm/case/load_case.hpp"
#include "openfoam/case/load_case.hpp"
#include "swe/case/load_case.hpp"

namespace fs = std::filesystem;

namespace {

TEST(ShippedConfigs, EveryJobAndCaseLoads) {
  std::map<std::string, int> loaded;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(COSIM_SOURCE_DIR) / "configs")) {
    if (!entry.is_regular_file() || entry.path().extension() != ".yaml") continue;
    const fs::path& file = entry.path();
    SCOPED_TRACE(file.string());
    const std::string kind = YAML::LoadFile(file.string())["kind"].as<std::string>("");
    try {
      if (kind == "job") {
        (void)cosim::job::load_job(file);
      } else if (kind == "mpm_case") {
        (void)mpm::load_case(file);
      } else if (kind == "swe_case") {
        (void)swe::load_case(file);
      } else if (kind == "ice_case") {
        (void)ice::load_case(file);
      } else if (kind == "openfoam_case") {
        (void)openfoam::load_case(file);
      } else if (kind != "test_participant") {
        ADD_FAILURE() << "unknown kind '" << kind << "'";
        continue;
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    ++loaded[kind];
  }
  for (const auto& [kind, count] : loaded) fmt::print("  {:17s} {} files load\n", kind, count);
  EXPECT_GE(loaded["job"], 9);
  EXPECT_GE(loaded["mpm_case"], 16);
  EXPECT_GE(loaded["swe_case"], 12);
  EXPECT_GE(loaded["ice_case"], 3);
  EXPECT_GE(loaded["openfoam_case"], 1);
}

}  // namespace
