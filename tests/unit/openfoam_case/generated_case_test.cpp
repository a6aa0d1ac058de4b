#include "openfoam/case/generated_case.hpp"

#include <gtest/gtest.h>

#include <string>

#include "openfoam/case/load_case.hpp"
#include "openfoam/foam/control_dict.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace openfoam {
namespace {

using cosim::testing::read_text;

GeneratedCase dam_break() {
  GeneratedCase g;
  g.dimension = 2;
  g.origin = {0.0, 0.0, 0.0};
  g.upper = {0.4, 0.2, 0.05};
  g.cells = {8, 4, 1};
  g.gravity = {0.0, -9.81, 0.0};
  g.water = {1000.0, 1e-3};
  g.air = {1.0, 1.8e-5};
  g.water_regions.push_back({{0.0, 0.0, 0.0}, {0.1, 0.1, 0.05}});
  g.sides[1] = SideKind::slip;
  g.sides[3] = SideKind::atmosphere;
  return g;
}

TEST(OpenFoamGeneratedCase, WritesEveryFileTheSolverReads) {
  cosim::testing::ScratchDirectory dir;
  write_generated_case(dam_break(), dir.path());
  for (const char* f : {"system/blockMeshDict", "system/setFieldsDict", "system/fvSchemes",
                        "system/fvSolution", "constant/transportProperties", "constant/g",
                        "constant/turbulenceProperties", "0/alpha.water", "0/U", "0/p_rgh"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / f)) << f;
  }
}

TEST(OpenFoamGeneratedCase, TheBlockHasTheCellsAndEachSideItsPatchType) {
  cosim::testing::ScratchDirectory dir;
  write_generated_case(dam_break(), dir.path());
  const std::string mesh = read_text(dir / "system/blockMeshDict");
  EXPECT_NE(mesh.find("hex (0 1 2 3 4 5 6 7) (8 4 1)"), std::string::npos) << mesh;
  EXPECT_NE(mesh.find("x_min\n    {\n        type wall;"), std::string::npos) << mesh;
  EXPECT_NE(mesh.find("y_max\n    {\n        type patch;"), std::string::npos) << mesh;
  EXPECT_NE(mesh.find("z_min\n    {\n        type empty;"), std::string::npos) << mesh;
  EXPECT_NE(mesh.find("z_max\n    {\n        type empty;"), std::string::npos) << mesh;
}

TEST(OpenFoamGeneratedCase, FieldsCarryTheSidesConditions) {
  cosim::testing::ScratchDirectory dir;
  write_generated_case(dam_break(), dir.path());
  const std::string u = read_text(dir / "0/U");
  EXPECT_NE(u.find("x_min\n    {\n        type noSlip;"), std::string::npos) << u;
  EXPECT_NE(u.find("x_max\n    {\n        type slip;"), std::string::npos) << u;
  EXPECT_NE(u.find("y_max\n    {\n        type pressureInletOutletVelocity;"), std::string::npos)
      << u;
  const std::string p = read_text(dir / "0/p_rgh");
  EXPECT_NE(p.find("y_max\n    {\n        type totalPressure; p0 uniform 0;"), std::string::npos)
      << p;
  EXPECT_NE(p.find("y_min\n    {\n        type fixedFluxPressure;"), std::string::npos) << p;
  const std::string alpha = read_text(dir / "0/alpha.water");
  EXPECT_NE(alpha.find("type inletOutlet; inletValue uniform 0;"), std::string::npos) << alpha;
}

TEST(OpenFoamGeneratedCase, APressureSideHoldsPRghAndLetsWaterIn) {
  GeneratedCase g = dam_break();
  g.sides[0] = SideKind::pressure;
  g.side_pressure[0] = 151987.5;
  cosim::testing::ScratchDirectory dir;
  write_generated_case(g, dir.path());
  const std::string mesh = read_text(dir / "system/blockMeshDict");
  EXPECT_NE(mesh.find("x_min\n    {\n        type patch;"), std::string::npos) << mesh;
  const std::string p = read_text(dir / "0/p_rgh");
  EXPECT_NE(p.find("x_min\n    {\n        type fixedValue; value uniform 151987.5;"),
            std::string::npos)
      << p;
  const std::string alpha = read_text(dir / "0/alpha.water");
  EXPECT_NE(alpha.find("x_min\n    {\n        type inletOutlet; inletValue uniform 1;"),
            std::string::npos)
      << alpha;
}

TEST(OpenFoamGeneratedCase, TheSoilsCloudHasOnlyItsDragAndAnImmenseDensity) {
  cosim::testing::ScratchDirectory dir;
  SoilSettings cloud;
  write_generated_case(dam_break(), dir.path(), &cloud);
  const std::string k = read_text(dir / "constant/kinematicCloudProperties");
  for (const char* entry : {"ErgunWenYuDrag", "alphac alphac;", "rho0 2650000;", "alphaMax 0.99;",
                            "U semiImplicit 1;", "packingModel none;", "injectionModels"}) {
    EXPECT_NE(k.find(entry), std::string::npos) << entry << "\n" << k;
  }
  EXPECT_EQ(k.find("gravity"), std::string::npos) << k;
  EXPECT_NE(read_text(dir / "system/fvSchemes").find("div((((alphac*rho)*nuEff)"),
            std::string::npos);
}

TEST(OpenFoamGeneratedCase, KinematicViscosityIsTheDynamicOneOverTheDensity) {
  cosim::testing::ScratchDirectory dir;
  write_generated_case(dam_break(), dir.path());
  const std::string t = read_text(dir / "constant/transportProperties");
  EXPECT_NE(t.find("nu 9.9999999999999995e-07;"), std::string::npos) << t;  // 1e-3 / 1000
  EXPECT_NE(t.find("nu 1.8e-05;"), std::string::npos) << t;
  EXPECT_NE(t.find("rho 1000;"), std::string::npos) << t;
}

TEST(OpenFoamGeneratedCase, WaterRegionsSpanThe2dThickness) {
  cosim::testing::ScratchDirectory dir;
  write_generated_case(dam_break(), dir.path());
  const std::string s = read_text(dir / "system/setFieldsDict");
  EXPECT_NE(s.find("box (0 0 -1) (0.10000000000000001 0.10000000000000001 1.05);"),
            std::string::npos)
      << s;
}

TEST(OpenFoamControlDict, RestartsFromTheLatestTimeAndWritesEveryFieldAtTheEnd) {
  const std::string d = control_dict({.application = "interFoam",
                                      .end_time = 0.25,
                                      .time_step = 1e-3,
                                      .write_every = 50,
                                      .write_density_at = {},
                                      .write_steps_between = {}});
  for (const char* entry :
       {"application interFoam;", "startFrom latestTime;", "endTime 0.25;", "deltaT 0.001;",
        "writeControl timeStep;", "writeInterval 50;", "adjustTimeStep no;",
        "runTimeModifiable false;", "timeFormat general;", "timePrecision 10;"}) {
    EXPECT_NE(d.find(entry), std::string::npos) << entry << "\n" << d;
  }
}

}  // namespace
}  // namespace openfoam
