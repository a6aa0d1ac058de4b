#include "openfoam/case/generated_case.hpp"

#include <fmt/format.h>

#include <string>

#include "cosim/io/files.hpp"
#include "openfoam/foam/foam_file_header.hpp"

namespace openfoam {

namespace {

constexpr const char* patch_names[] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};

// The block's vertices 0-7 in blockMesh's order and each side's face (its
// four vertices ordered so that the normal points out of the block).
constexpr int side_faces[6][4] = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                  {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};

std::string vector_text(const Vector3& v) {
  return fmt::format("({:.17g} {:.17g} {:.17g})", v[0], v[1], v[2]);
}

bool is_empty_side(const GeneratedCase& c, int side) {
  return c.dimension == 2 && side >= 4;
}

bool is_open(SideKind kind) {
  return kind == SideKind::atmosphere || kind == SideKind::pressure;
}

std::string block_mesh_dict(const GeneratedCase& c) {
  const Vector3& a = c.origin;
  const Vector3& b = c.upper;
  std::string text = foam_file_header({"dictionary", "system", "blockMeshDict"});
  text += "scale 1;\n\nvertices\n(\n";
  const Vector3 corners[8] = {{a[0], a[1], a[2]}, {b[0], a[1], a[2]}, {b[0], b[1], a[2]},
                              {a[0], b[1], a[2]}, {a[0], a[1], b[2]}, {b[0], a[1], b[2]},
                              {b[0], b[1], b[2]}, {a[0], b[1], b[2]}};
  for (const Vector3& v : corners) text += "    " + vector_text(v) + "\n";
  text += ");\n\n";
  text +=
      fmt::format("blocks\n(\n    hex (0 1 2 3 4 5 6 7) ({} {} {}) simpleGrading (1 1 1)\n);\n\n",
                  c.cells[0], c.cells[1], c.cells[2]);
  text += "edges\n(\n);\n\nboundary\n(\n";
  for (int s = 0; s < 6; ++s) {
    const auto& f = side_faces[s];
    const char* type = is_empty_side(c, s)                             ? "empty"
                       : is_open(c.sides[static_cast<std::size_t>(s)]) ? "patch"
                                                                       : "wall";
    text +=
        fmt::format("    {}\n    {{\n        type {};\n        faces (({} {} {} {}));\n    }}\n",
                    patch_names[s], type, f[0], f[1], f[2], f[3]);
  }
  text += ");\n\nmergePatchPairs\n(\n);\n";
  return text;
}

std::string set_fields_dict(const GeneratedCase& c) {
  std::string text = foam_file_header({"dictionary", "system", "setFieldsDict"});
  text += "defaultFieldValues\n(\n    volScalarFieldValue alpha.water 0\n);\n\nregions\n(\n";
  for (const WaterBox& w : c.water_regions) {
    Vector3 lower = w.lower;
    Vector3 upper = w.upper;
    if (c.dimension == 2) {
      // The whole thickness: setFields tests the cell centres.
      lower[2] = c.origin[2] - 1.0;
      upper[2] = c.upper[2] + 1.0;
    }
    text += fmt::format(
        "    boxToCell\n    {{\n        box {} {};\n        fieldValues\n        (\n"
        "            volScalarFieldValue alpha.water 1\n        );\n    }}\n",
        vector_text(lower), vector_text(upper));
  }
  text += ");\n";
  return text;
}

std::string transport_properties(const GeneratedCase& c) {
  std::string text = foam_file_header({"dictionary", "constant", "transportProperties"});
  const auto phase = [](const char* name, const FluidProperties& f) {
    return fmt::format(
        "{}\n{{\n    transportModel Newtonian;\n    nu {:.17g};\n    rho {:.17g};\n}}\n\n", name,
        f.viscosity / f.density, f.density);
  };
  text += "phases (water air);\n\n" + phase("water", c.water) + phase("air", c.air);
  text += fmt::format("sigma {:.17g};\n", c.surface_tension);
  return text;
}

std::string gravity(const GeneratedCase& c) {
  return foam_file_header({"uniformDimensionedVectorField", "constant", "g"}) +
         "dimensions [0 1 -2 0 0 0 0];\nvalue " + vector_text(c.gravity) + ";\n";
}

std::string turbulence_properties() {
  return foam_file_header({"dictionary", "constant", "turbulenceProperties"}) +
         "simulationType laminar;\n";
}

// Van Leer for the water fraction with MULES' interface compression, the
// momentum upwinded to second order, Euler in time (a restart restores no
// older time level).
std::string fv_schemes() {
  return foam_file_header({"dictionary", "system", "fvSchemes"}) +
         "ddtSchemes\n{\n    default Euler;\n}\n\n"
         "gradSchemes\n{\n    default Gauss linear;\n}\n\n"
         "divSchemes\n{\n    div(rhoPhi,U) Gauss linearUpwind grad(U);\n"
         "    div(phi,alpha) Gauss vanLeer;\n    div(phirb,alpha) Gauss linear;\n"
         "    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;\n"
         "    div((((alphac*rho)*nuEff)*dev2(T(grad(U))))) Gauss linear;\n}\n\n"
         "laplacianSchemes\n{\n    default Gauss linear corrected;\n}\n\n"
         "interpolationSchemes\n{\n    default linear;\n}\n\n"
         "snGradSchemes\n{\n    default corrected;\n}\n";
}

// p_rgh to a tight absolute tolerance in its final corrector (the pressure
// the soil reads), the start-up flux correction pcorr that every restart
// runs.
std::string fv_solution() {
  return foam_file_header({"dictionary", "system", "fvSolution"}) +
         "solvers\n{\n"
         "    \"alpha.water.*\"\n    {\n        nAlphaCorr 2;\n        nAlphaSubCycles 1;\n"
         "        cAlpha 1;\n        MULESCorr yes;\n        nLimiterIter 5;\n"
         "        solver smoothSolver;\n        smoother symGaussSeidel;\n"
         "        tolerance 1e-8;\n        relTol 0;\n    }\n\n"
         "    \"pcorr.*\"\n    {\n        solver PCG;\n        preconditioner DIC;\n"
         "        tolerance 1e-5;\n        relTol 0;\n    }\n\n"
         "    p_rgh\n    {\n        solver PCG;\n        preconditioner DIC;\n"
         "        tolerance 1e-7;\n        relTol 0.05;\n    }\n\n"
         "    p_rghFinal\n    {\n        $p_rgh;\n        relTol 0;\n    }\n\n"
         "    U\n    {\n        solver smoothSolver;\n        smoother symGaussSeidel;\n"
         "        tolerance 1e-6;\n        relTol 0;\n    }\n}\n\n"
         "PIMPLE\n{\n    momentumPredictor no;\n    nOuterCorrectors 1;\n    nCorrectors 3;\n"
         "    nNonOrthogonalCorrectors 0;\n}\n\n"
         "relaxationFactors\n{\n    equations\n    {\n        \".*\" 1;\n    }\n}\n";
}

// The initial field files: each side's condition for alpha.water, U and
// p_rgh (the findings' table; slip walls take OpenFOAM's slip for U).
std::string side_condition(const GeneratedCase& c, int side, const std::string& field) {
  if (is_empty_side(c, side)) return "type empty;";
  const SideKind kind = c.sides[static_cast<std::size_t>(side)];
  if (field == "alpha.water") {
    switch (kind) {
      case SideKind::atmosphere:
        return "type inletOutlet; inletValue uniform 0; value uniform 0;";
      case SideKind::pressure:
        return "type inletOutlet; inletValue uniform 1; value uniform 1;";
      default:
        return "type zeroGradient;";
    }
  }
  if (field == "U") {
    switch (kind) {
      case SideKind::wall:
        return "type noSlip;";
      case SideKind::slip:
        return "type slip;";
      case SideKind::atmosphere:
      case SideKind::pressure:
        return "type pressureInletOutletVelocity; value uniform (0 0 0);";
    }
  }
  switch (kind) {
    case SideKind::atmosphere:
      return "type totalPressure; p0 uniform 0;";
    case SideKind::pressure:
      return fmt::format("type fixedValue; value uniform {:.17g};",
                         c.side_pressure[static_cast<std::size_t>(side)]);
    default:
      return "type fixedFluxPressure; value uniform 0;";
  }
}

std::string initial_field(const GeneratedCase& c, const std::string& field, const char* foam_class,
                          const char* dimensions, const char* value) {
  std::string text = foam_file_header({foam_class, "0", field});
  text += fmt::format("dimensions {};\n\ninternalField uniform {};\n\nboundaryField\n{{\n",
                      dimensions, value);
  for (int s = 0; s < 6; ++s) {
    text += fmt::format("    {}\n    {{\n        {}\n    }}\n", patch_names[s],
                        side_condition(c, s, field));
  }
  text += "}\n";
  return text;
}

}  // namespace

std::string soil_cloud_properties(const SoilSettings& cloud) {
  return foam_file_header({"dictionary", "constant", "kinematicCloudProperties"}) +
         "solution\n{\n    active true;\n    coupled true;\n    transient yes;\n"
         "    cellValueSourceCorrection off;\n    maxCo 0.3;\n"
         "    interpolationSchemes\n    {\n        rho cell;\n        U cellPoint;\n"
         "        mu cell;\n        alphac cell;\n    }\n"
         "    averagingMethod dual;\n    integrationSchemes\n    {\n        U Euler;\n    }\n"
         "    sourceTerms\n    {\n        schemes\n        {\n            U semiImplicit 1;\n"
         "        }\n    }\n}\n\n" +
         fmt::format("constantProperties\n{{\n    rho0 {};\n    alphaMax {};\n}}\n\n",
                     cloud.parcel_density, cloud.max_solid_fraction) +
         "subModels\n{\n    particleForces\n    {\n        ErgunWenYuDrag\n        {\n"
         "            alphac alphac;\n        }\n    }\n    injectionModels\n    {\n    }\n"
         "    dispersionModel none;\n    patchInteractionModel standardWallInteraction;\n"
         "    standardWallInteractionCoeffs\n    {\n        type rebound;\n    }\n"
         "    heatTransferModel none;\n    surfaceFilmModel none;\n    packingModel none;\n"
         "    dampingModel none;\n    isotropyModel none;\n    stochasticCollisionModel none;\n"
         "    radiation off;\n}\n\ncloudFunctions\n{\n}\n";
}

const char* side_patch_name(int side) {
  return patch_names[side];
}

void write_generated_case(const GeneratedCase& c, const std::filesystem::path& case_dir,
                          const SoilSettings* cloud) {
  for (const char* sub : {"system", "constant", "0"}) {
    std::filesystem::create_directories(case_dir / sub);
  }
  const auto write = [&](const char* name, const std::string& text) {
    cosim::write_file_atomically(case_dir / name, text);
  };
  write("system/blockMeshDict", block_mesh_dict(c));
  write("system/setFieldsDict", set_fields_dict(c));
  write("system/fvSchemes", fv_schemes());
  write("system/fvSolution", fv_solution());
  write("constant/transportProperties", transport_properties(c));
  write("constant/g", gravity(c));
  write("constant/turbulenceProperties", turbulence_properties());
  write("0/alpha.water", initial_field(c, "alpha.water", "volScalarField", "[0 0 0 0 0 0 0]", "0"));
  write("0/U", initial_field(c, "U", "volVectorField", "[0 1 -1 0 0 0 0]", "(0 0 0)"));
  write("0/p_rgh", initial_field(c, "p_rgh", "volScalarField", "[1 -1 -2 0 0 0 0]",
                                 fmt::format("{:.17g}", c.initial_pressure).c_str()));
  if (cloud) write("constant/kinematicCloudProperties", soil_cloud_properties(*cloud));
}

}  // namespace openfoam
