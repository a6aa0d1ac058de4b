#include "mpm/case/load_case.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>

#include "cosim/error.hpp"
#include "mpm/case/case_schema.hpp"
#include "replaced_text.hpp"
#include "scratch_directory.hpp"

namespace mpm {

using cosim::testing::replaced;

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A 2D case: 1 m x 1 m grid of 20 x 20 cells (h = 0.05 m), an elastic block
// [0.4, 0.6] x [0.5, 0.7] (4 x 4 cells, 2 x 2 particles each) and a rigid
// floor [0, 1] x [0, 0.1].
const char* const valid_case = R"(kind: mpm_case
name: drop
dimension: 2
grid: {origin: [0, 0], upper: [1, 1], cells: [20, 20]}
shape: gimp
time: {end_time: 0.1, safety_factor: 0.4}
gravity: [0, -9.81]
materials:
  rubber: {type: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
bodies:
  - name: block
    material: rubber
    geometry: {box: {min: [0.4, 0.5], max: [0.6, 0.7]}}
    particles_per_cell: 2
    initial_velocity: [0, -1]
  - name: floor
    rigid: {motion: fixed}
    density: 2000
    geometry: {box: {min: [0, 0], max: [1, 0.1]}}
contact: {enabled: true, friction: 0.2, pairs: [{bodies: [floor, block], friction: 0.5}]}
boundaries: {x_min: slip, x_max: {frictional: 0.3}, y_min: fixed}
loads:
  - {name: top, body: block, region: {min: [0.4, 0.67], max: [0.6, 0.7]}, pressure: 1000}
probes:
  - {name: centre, body: block, position: [0.5, 0.6]}
output: {every: 0.01, probe_every: 0.001}
)";

// The valid case with the load region starting at height y.
std::string with_load_from(double y) {
  return replaced(valid_case, "min: [0.4, 0.67]", "min: [0.4, " + std::to_string(y) + "]");
}

// The message of the InputError loading `text` throws.
std::string error_of(const std::string& text, const fs::path& name = "case.yaml") {
  try {
    load_case_text(text, name);
  } catch (const cosim::InputError& e) {
    EXPECT_EQ(e.code(), cosim::ExitCode::bad_input);
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(MpmCaseLoad, ReadsEveryPartOfAValidCase) {
  const CaseDescription c = load_case_text(valid_case, "case.yaml");
  EXPECT_EQ(c.name, "drop");
  EXPECT_EQ(c.dimension, 2);
  EXPECT_DOUBLE_EQ(c.grid.spacing.x(), 0.05);
  EXPECT_EQ(c.grid.cells[0], 20);
  EXPECT_EQ(c.shape, ShapeKind::gimp);
  EXPECT_EQ(c.scheme, UpdateScheme::musl);
  EXPECT_EQ(c.gimp_domain, GimpDomain::initial);
  EXPECT_DOUBLE_EQ(c.time.safety_factor, 0.4);
  EXPECT_DOUBLE_EQ(c.gravity.y(), -9.81);
  ASSERT_EQ(c.materials.size(), 1u);
  EXPECT_EQ(c.material_names[0], "rubber");
  EXPECT_DOUBLE_EQ(c.materials[0]->density(), 1000.0);

  ASSERT_EQ(c.bodies.size(), 2u);
  const BodySpec& block = c.bodies[0];
  EXPECT_EQ(block.material, 0);
  EXPECT_EQ(block.positions.size(), 64u);  // 4 x 4 cells, 2 x 2 per cell
  const double area = std::accumulate(block.volumes.begin(), block.volumes.end(), 0.0);
  EXPECT_NEAR(area, 0.04, 1e-12);
  EXPECT_DOUBLE_EQ(block.half_lengths[0].x(), 0.0125);
  EXPECT_DOUBLE_EQ(block.initial_velocity.y(), -1.0);
  const BodySpec& floor = c.bodies[1];
  ASSERT_TRUE(floor.rigid.has_value());
  EXPECT_EQ(floor.rigid->kind, RigidMotion::Kind::fixed);
  EXPECT_DOUBLE_EQ(floor.density_override, 2000.0);
  EXPECT_EQ(floor.positions.size(), 20u * 2u * 4u);

  EXPECT_TRUE(c.contact.enabled);
  EXPECT_DOUBLE_EQ(c.contact.friction_between(1, 0), 0.5);
  EXPECT_EQ(c.boundaries[0].kind, FaceCondition::Kind::slip);
  EXPECT_EQ(c.boundaries[1].kind, FaceCondition::Kind::frictional);
  EXPECT_DOUBLE_EQ(c.boundaries[1].friction, 0.3);
  EXPECT_EQ(c.boundaries[2].kind, FaceCondition::Kind::fixed);
  EXPECT_EQ(c.boundaries[3].kind, FaceCondition::Kind::free);

  ASSERT_EQ(c.loads.size(), 1u);
  EXPECT_EQ(c.loads[0].particles.size(), 8u);  // the top row of the block
  for (const auto p : c.loads[0].particles) {
    ASSERT_LT(p, block.positions.size());
    EXPECT_GT(block.positions[p].y(), 0.67);
  }
  EXPECT_EQ(c.loads[0].face, 3);
  EXPECT_DOUBLE_EQ(*c.loads[0].pressure, 1000.0);

  ASSERT_EQ(c.probes.size(), 1u);
  const Vec3d at = block.positions[c.probes[0].particle];
  EXPECT_LE((at - Vec3d(0.5, 0.6, 0)).norm(), 0.0125 * std::sqrt(2.0) + 1e-12);
  EXPECT_DOUBLE_EQ(c.output.every, 0.01);
  EXPECT_DOUBLE_EQ(c.output.probe_every, 0.001);
}

// A load's ramp: linear by default, or cycloidal (s - sin(2 pi s) / (2 pi)
// of s = t / T: half the load at half the ramp, its rate zero at both ends).
TEST(MpmCaseLoad, ALoadRampsLinearlyOrCycloidally) {
  const std::string ramped =
      replaced(valid_case, "pressure: 1000}", "pressure: 1000, ramp_time: 0.2}");
  const LoadSpec linear = load_case_text(ramped, "case.yaml").loads.at(0);
  EXPECT_EQ(linear.ramp_shape, LoadSpec::RampShape::linear);
  EXPECT_DOUBLE_EQ(linear.ramp_factor(0.05), 0.25);
  EXPECT_DOUBLE_EQ(linear.ramp_factor(0.3), 1.0);
  const LoadSpec cycloidal =
      load_case_text(replaced(ramped, "ramp_time: 0.2}", "ramp_time: 0.2, ramp_shape: cycloidal}"),
                     "case.yaml")
          .loads.at(0);
  EXPECT_EQ(cycloidal.ramp_shape, LoadSpec::RampShape::cycloidal);
  EXPECT_DOUBLE_EQ(cycloidal.ramp_factor(0.0), 0.0);
  EXPECT_NEAR(cycloidal.ramp_factor(0.1), 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(cycloidal.ramp_factor(0.2), 1.0);
  EXPECT_DOUBLE_EQ(cycloidal.ramp_factor(0.5), 1.0);
  // Its rate at the ends: a small step changes it by O(step^3), not O(step).
  const double h = 1e-4;
  EXPECT_LT(cycloidal.ramp_factor(h), 1e-8);  // a linear ramp: 5e-4
  EXPECT_GT(1.0 - cycloidal.ramp_factor(0.2 - h), 0.0);
  EXPECT_LT(1.0 - cycloidal.ramp_factor(0.2 - h), 1e-8);
  EXPECT_THAT(error_of(replaced(ramped, "ramp_time: 0.2}", "ramp_time: 0.2, ramp_shape: cubic}")),
              HasSubstr("ramp_shape"));
}

TEST(MpmCaseLoad, ReadsTheGimpDomainUpdate) {
  std::string text = valid_case;
  text.replace(text.find("shape: gimp\n"), 12, "shape: gimp\ngimp_domain: deformed\n");
  EXPECT_EQ(load_case_text(text, "case.yaml").gimp_domain, GimpDomain::deformed);
}

TEST(MpmCaseLoad, ProbeIndicesAreGlobalInBodyOrder) {
  const std::string text = replaced(valid_case, "{name: centre, body: block, position: [0.5, 0.6]}",
                                    "{name: ground, body: floor, position: [0.5, 0.05]}");
  const CaseDescription c = load_case_text(text, "case.yaml");
  const std::size_t p = c.probes[0].particle;
  ASSERT_GE(p, c.bodies[0].positions.size());
  const Vec3d at = c.bodies[1].positions[p - c.bodies[0].positions.size()];
  EXPECT_NEAR(at.x(), 0.5, 0.0125 + 1e-12);
  EXPECT_NEAR(at.y(), 0.05, 0.0125 + 1e-12);
}

TEST(MpmCaseLoad, UnknownKeyIsLocatedWithASuggestion) {
  const std::string message = error_of(replaced(valid_case, "gravity:", "gravty:"));
  EXPECT_THAT(message, HasSubstr("case.yaml:7:1: key 'gravty'"));
  EXPECT_THAT(message, HasSubstr("did you mean 'gravity'"));
}

TEST(MpmCaseLoad, MaterialParameterErrorsNameTheMaterialKey) {
  EXPECT_THAT(error_of(replaced(valid_case, "poisson_ratio: 0.3", "poisson_ratio: 0.5")),
              HasSubstr("case.yaml:9:"));
  EXPECT_THAT(error_of(replaced(valid_case, "poisson_ratio: 0.3", "poisson_ratio: 0.5")),
              HasSubstr("materials.rubber.poisson_ratio"));
  EXPECT_THAT(error_of(replaced(valid_case, "youngs_modulus: 1.0e6", "youngs_modulus: 0")),
              HasSubstr("materials.rubber.youngs_modulus"));
  EXPECT_THAT(error_of(replaced(valid_case, "density: 1000", "density: -5")),
              HasSubstr("materials.rubber.density"));
}

TEST(MpmCaseLoad, UnknownMaterialIsRefusedWithASuggestion) {
  const std::string message = error_of(replaced(valid_case, "material: rubber", "material: rubbr"));
  EXPECT_THAT(message, HasSubstr("case.yaml:12:15: key 'bodies[0].material'"));
  EXPECT_THAT(message, HasSubstr("did you mean 'rubber'"));
}

TEST(MpmCaseLoad, ParticlesOutsideTheGridNameBodyAndPosition) {
  const std::string message = error_of(replaced(valid_case, "max: [0.6, 0.7]", "max: [0.6, 1.2]"));
  EXPECT_THAT(message, HasSubstr("case.yaml:13:15: key 'bodies[0].geometry'"));
  EXPECT_THAT(
      message,
      HasSubstr("body 'block' has particles outside the grid, the first at (0.4125, 1.0125)"));
}

TEST(MpmCaseLoad, BodyWithoutParticlesIsRefused) {
  // Between two rows of particle sites (y = 0.5125 and 0.5375).
  const std::string message = error_of(replaced(valid_case, "{min: [0.4, 0.5], max: [0.6, 0.7]}",
                                                "{min: [0.4, 0.515], max: [0.6, 0.53]}"));
  EXPECT_THAT(message, HasSubstr("body 'block' seeds no particles"));
  EXPECT_THAT(message, HasSubstr("case.yaml:13:15: key 'bodies[0].geometry'"));
}

TEST(MpmCaseLoad, CountsBelowOneAreRefused) {
  EXPECT_THAT(error_of(replaced(valid_case, "particles_per_cell: 2", "particles_per_cell: 0")),
              HasSubstr("key 'bodies[0].particles_per_cell'"));
  EXPECT_THAT(error_of(replaced(valid_case, "particles_per_cell: 2", "particles_per_cell: [2, 0]")),
              HasSubstr("particles_per_cell must be whole numbers >= 1"));
  EXPECT_THAT(
      error_of(replaced(valid_case, "cells: [20, 20]", "cells: [20, 0]")),
      HasSubstr("case.yaml:4:46: key 'grid.cells': grid cells must be whole numbers >= 1, got 0"));
}

TEST(MpmCaseLoad, VectorsNeedOneValuePerDimension) {
  EXPECT_THAT(error_of(replaced(valid_case, "gravity: [0, -9.81]", "gravity: [0, -9.81, 0]")),
              HasSubstr("key 'gravity': expected 2 values (dimension: 2), got 3"));
}

TEST(MpmCaseLoad, ProbeOutsideItsBodyIsRefused) {
  const std::string message =
      error_of(replaced(valid_case, "position: [0.5, 0.6]", "position: [0.9, 0.9]"));
  EXPECT_THAT(message, HasSubstr("key 'probes[0].position'"));
  EXPECT_THAT(message, HasSubstr("probe 'centre' at (0.9, 0.9) is outside body 'block'"));
}

TEST(MpmCaseLoad, UnknownBodyInAContactPairIsRefused) {
  EXPECT_THAT(error_of(replaced(valid_case, "bodies: [floor, block]", "bodies: [flor, block]")),
              HasSubstr("unknown body 'flor'; did you mean 'floor'"));
}

TEST(MpmCaseLoad, GridNeedsUpperOrSpacing) {
  EXPECT_THAT(
      error_of(replaced(valid_case, "upper: [1, 1]", "upper: [1, 1], spacing: [0.05, 0.05]")),
      HasSubstr("give exactly one of `upper` and `spacing`"));
  const auto c =
      load_case_text(replaced(valid_case, "upper: [1, 1]", "spacing: [0.05, 0.05]"), "case.yaml");
  EXPECT_DOUBLE_EQ(c.grid.spacing.y(), 0.05);
}

TEST(MpmCaseLoad, PrescribedRigidMotionReadsItsHistoryRelativeToTheCase) {
  const cosim::testing::ScratchDirectory dir;
  std::ofstream(dir / "shake.csv") << "time [s],vx [m/s],vy [m/s]\n0,0,0\n0.1,0.2,0\n0.2,-0.2,0\n";
  const std::string text = replaced(valid_case, "rigid: {motion: fixed}",
                                    "rigid: {motion: prescribed, velocity_history: shake.csv}");
  const CaseDescription c = load_case_text(text, dir / "case.yaml");
  const RigidMotion& motion = *c.bodies[1].rigid;
  EXPECT_EQ(motion.kind, RigidMotion::Kind::prescribed);
  ASSERT_EQ(motion.velocity.time.size(), 3u);
  EXPECT_NEAR(motion.velocity.at(0.05).x(), 0.1, 1e-15);
}

TEST(MpmCaseLoad, BadVelocityHistoryLineIsLocatedInTheCsv) {
  const cosim::testing::ScratchDirectory dir;
  std::ofstream(dir / "shake.csv") << "time [s],vx [m/s],vy [m/s]\n0,0,0\n0.1,abc,0\n";
  const std::string text = replaced(valid_case, "rigid: {motion: fixed}",
                                    "rigid: {motion: prescribed, velocity_history: shake.csv}");
  const std::string message = error_of(text, dir / "case.yaml");
  EXPECT_THAT(message, HasSubstr("shake.csv:3:5: key 'bodies[1].rigid.velocity_history'"));
  EXPECT_THAT(message, HasSubstr("'abc' in column 'vx [m/s]' is not a finite number"));
}

TEST(MpmCaseLoad, VelocityHistoryHeaderAndOrderAreChecked) {
  const cosim::testing::ScratchDirectory dir;
  const std::string text = replaced(valid_case, "rigid: {motion: fixed}",
                                    "rigid: {motion: prescribed, velocity_history: shake.csv}");
  std::ofstream(dir / "shake.csv") << "t,vx,vy\n0,0,0\n";
  EXPECT_THAT(error_of(text, dir / "case.yaml"),
              HasSubstr("shake.csv:1:1: key 'bodies[1].rigid.velocity_history': velocity history "
                        "header must be 'time [s],vx [m/s],vy [m/s]'"));
  std::ofstream(dir / "shake.csv") << "time [s],vx [m/s],vy [m/s]\n0,0,0\n0,1,0\n";
  EXPECT_THAT(error_of(text, dir / "case.yaml"), HasSubstr("shake.csv:3:1:"));
  EXPECT_THAT(error_of(text, dir / "case.yaml"), HasSubstr("times must increase"));
}

TEST(MpmCaseLoad, PrescribedMotionNeedsAHistory) {
  EXPECT_THAT(
      error_of(replaced(valid_case, "rigid: {motion: fixed}", "rigid: {motion: prescribed}")),
      HasSubstr("motion: prescribed needs a `velocity_history`"));
}

TEST(MpmCaseLoad, PorousBodyNeedsAGrainSizeForKozenyCarman) {
  const std::string porous =
      replaced(valid_case, "initial_velocity: [0, -1]", "porous: {porosity: 0.4}");
  EXPECT_THAT(error_of(porous), HasSubstr("needs `grain_size`"));
  const auto c = load_case_text(replaced(valid_case, "initial_velocity: [0, -1]",
                                         "porous: {porosity: 0.4, grain_size: 1.0e-3}"),
                                "case.yaml");
  ASSERT_TRUE(c.bodies[0].porous.has_value());
  EXPECT_DOUBLE_EQ(c.bodies[0].porous->porosity, 0.4);
  EXPECT_EQ(c.bodies[0].porous->permeability_model, PermeabilityModel::kozeny_carman_pan);
}

TEST(MpmCaseLoad, TwoDimensionalCaseHasNoZFaces) {
  EXPECT_THAT(error_of(replaced(valid_case, "y_min: fixed", "y_min: fixed, z_min: fixed")),
              HasSubstr("key 'boundaries.z_min': a 2D case has no z faces"));
}

TEST(MpmCaseLoad, MissingFileIsABadInput) {
  try {
    load_case("/nonexistent/case.yaml");
    FAIL() << "no error";
  } catch (const cosim::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("/nonexistent/case.yaml"));
  }
}

TEST(MpmCaseLoad, SeedsPolygonsR2AndPerDirectionCounts) {
  // Right triangle with legs 0.2 m: half of the 0.2 x 0.2 box.
  const std::string polygon =
      replaced(with_load_from(0.55), "{box: {min: [0.4, 0.5], max: [0.6, 0.7]}}",
               "{polygon: [[0.4, 0.5], [0.6, 0.5], [0.4, 0.7]]}");
  const auto triangle = load_case_text(polygon, "case.yaml").bodies[0];
  const double area = std::accumulate(triangle.volumes.begin(), triangle.volumes.end(), 0.0);
  EXPECT_NEAR(area, 0.02, 0.04 / 64 * 8 + 1e-12) << "triangle area from particle volumes";

  const auto r2 = load_case_text(replaced(valid_case, "particles_per_cell: 2",
                                          "particles_per_cell: 3\n    seeding: r2"),
                                 "case.yaml")
                      .bodies[0];
  EXPECT_EQ(r2.positions.size(), 16u * 9u);  // 4 x 4 cells, 3^2 per cell

  const auto uneven =
      load_case_text(replaced(valid_case, "particles_per_cell: 2", "particles_per_cell: [1, 3]"),
                     "case.yaml")
          .bodies[0];
  EXPECT_EQ(uneven.positions.size(), 16u * 3u);
  EXPECT_DOUBLE_EQ(uneven.half_lengths[0].x(), 0.025);
  EXPECT_NEAR(uneven.half_lengths[0].y(), 0.05 / 6, 1e-15);
  EXPECT_NEAR(uneven.volumes[0], 0.05 * 0.05 / 3, 1e-15);
}

TEST(MpmCaseLoad, DegeneratePolygonIsLocatedAtItsKey) {
  const std::string message =
      error_of(replaced(valid_case, "{box: {min: [0.4, 0.5], max: [0.6, 0.7]}}",
                        "{polygon: [[0.4, 0.5], [0.5, 0.5], [0.6, 0.5]]}"));
  EXPECT_THAT(message, HasSubstr("case.yaml:13:25: key 'bodies[0].geometry.polygon'"));
}

TEST(MpmCaseLoad, ReadsParticlesFromAPointsFile) {
  const cosim::testing::ScratchDirectory dir;
  std::ofstream(dir / "block.csv") << "x,y,volume\n0.5,0.5,0.01\n0.5,0.6,0.01\n";
  const auto c =
      load_case_text(replaced(with_load_from(0.55), "{box: {min: [0.4, 0.5], max: [0.6, 0.7]}}",
                              "{points: block.csv}"),
                     dir / "case.yaml");
  ASSERT_EQ(c.bodies[0].positions.size(), 2u);
  EXPECT_DOUBLE_EQ(c.bodies[0].positions[1].y(), 0.6);
  EXPECT_DOUBLE_EQ(c.bodies[0].volumes[0], 0.01);

  std::ofstream(dir / "block.csv") << "x,y,volume\n0.5,0.5,0.01\n0.5,0.6,-1\n";
  const std::string message =
      error_of(replaced(with_load_from(0.55), "{box: {min: [0.4, 0.5], max: [0.6, 0.7]}}",
                        "{points: block.csv}"),
               dir / "case.yaml");
  EXPECT_THAT(message, HasSubstr("block.csv:3:"));
  EXPECT_THAT(message, HasSubstr("key 'bodies[0].geometry.points'"));
}

TEST(MpmCaseLoad, ThreeDimensionalBoxAndPolyhedron) {
  const std::string text = R"(kind: mpm_case
dimension: 3
grid: {origin: [0, 0, 0], spacing: [0.1, 0.1, 0.1], cells: [4, 4, 4]}
time: {end_time: 0.1}
materials:
  steel: {type: linear_elastic, density: 7800, youngs_modulus: 2.0e11, poisson_ratio: 0.3}
bodies:
  - name: cube
    material: steel
    geometry: {box: {min: [0.1, 0.1, 0.1], max: [0.3, 0.3, 0.3]}}
  - name: tetra
    material: steel
    particles_per_cell: 4
    geometry:
      polyhedron:
        vertices: [[0, 0, 0], [0.4, 0, 0], [0, 0.4, 0], [0, 0, 0.4]]
        triangles: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
)";
  const auto c = load_case_text(text, "case3d.yaml");
  EXPECT_EQ(c.bodies[0].positions.size(), 64u);  // 2^3 cells x 2^3
  const double volume =
      std::accumulate(c.bodies[1].volumes.begin(), c.bodies[1].volumes.end(), 0.0);
  EXPECT_NEAR(volume, 0.4 * 0.4 * 0.4 / 6, 0.15 * 0.4 * 0.4 * 0.4 / 6)
      << "tetrahedron volume from particles";
}

TEST(MpmCaseHelp, ListsCaseKeysAndMaterialModels) {
  const std::string help = mpm_case_help();
  for (const char* key : {"grid.origin", "time.min_time_step", "bodies[].geometry.box.min",
                          "bodies[].rigid.velocity_history", "bodies[].porous.permeability.model",
                          "contact.pairs[].friction", "boundaries.x_min", "loads[].ramp_time",
                          "probes[].position", "output.probe_every", "gimp_domain", "threads"})
    EXPECT_THAT(help, HasSubstr(key));
  EXPECT_THAT(help, HasSubstr("materials.<name> with type: linear_elastic"));
}

}  // namespace
}  // namespace mpm
