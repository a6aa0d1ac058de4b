#include "openfoam/foam/field_file.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "openfoam/foam/foam_file_header.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace openfoam {
namespace {

namespace fs = std::filesystem;
using cosim::testing::read_text;

// The layout OpenFOAM v1912 writes (banner comment, header, blank lines, the
// list size on its own line); the banner here is our own text.
constexpr const char* banner =
    R"(/*--------------------------------*- C++ -*----------------------------------*\
| sample written for the cosim tests in OpenFOAM's layout                     |
\*---------------------------------------------------------------------------*/
)";

std::string vol_header(const std::string& class_name, const std::string& object) {
  return std::string(banner) + "FoamFile\n{\n    version     2.0;\n    format      ascii;\n" +
         "    class       " + class_name + ";\n    location    \"0.05\";\n    object      " +
         object + ";\n}\n// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n";
}

std::string dam_break_boundary() {
  return R"(boundaryField
{
    leftWall
    {
        type            calculated;
        value           nonuniform List<scalar> 
3
(
1956.4
1897.69
1839.14
)
;
    }
    atmosphere
    {
        type            calculated;
        value           uniform 0;
    }
    defaultFaces
    {
        type            empty;
    }
}


// ************************************************************************* //
)";
}

constexpr const char* walls_zero_gradient = "    walls\n    {\n        type zeroGradient;\n    }";

class OpenFoamFieldFile : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& text) const {
    return scratch_.write(name, text);
  }

  cosim::testing::ScratchDirectory scratch_;
  fs::path dir_ = scratch_.path();
};

// The message of the cosim::Error that `read` throws, its exit code checked.
template <class Read>
std::string error_of(Read read, cosim::ExitCode code = cosim::ExitCode::participant_failed) {
  try {
    read();
  } catch (const cosim::Error& e) {
    EXPECT_EQ(cosim::to_int(e.code()), cosim::to_int(code)) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no cosim::Error thrown";
  return {};
}

std::vector<std::uint64_t> bits_of(const std::vector<double>& values) {
  std::vector<std::uint64_t> bits;
  for (const double v : values) bits.push_back(std::bit_cast<std::uint64_t>(v));
  return bits;
}

TEST_F(OpenFoamFieldFile, ReadsANonuniformScalarFieldInOpenFoamsLayout) {
  const fs::path file = write("p", vol_header("volScalarField", "p") +
                                       "dimensions      [1 -1 -2 0 0 0 0];\n\n\n"
                                       "internalField   nonuniform List<scalar> \n4\n(\n"
                                       "1956.4\n-3.75428\n1.11212e-06\n0\n)\n;\n\n" +
                                       dam_break_boundary());
  EXPECT_EQ(read_internal_field(file, FieldType::scalar, 4),
            (std::vector<double>{1956.4, -3.75428, 1.11212e-06, 0.0}));
}

TEST_F(OpenFoamFieldFile, ReadsANonuniformVectorFieldFlattened) {
  const fs::path file = write("U", vol_header("volVectorField", "U") +
                                       "dimensions      [0 1 -1 0 0 0 0];\n\n\n"
                                       "internalField   nonuniform List<vector> \n3\n(\n"
                                       "(-0.00657537 0.0718863 0)\n(1 2 3)\n(4e-3 -5 6)\n)\n;\n\n" +
                                       "boundaryField\n{\n    lowerWall\n    {\n        type "
                                       "noSlip;\n    }\n}\n");
  EXPECT_EQ(read_internal_field(file, FieldType::vector, 3),
            (std::vector<double>{-0.00657537, 0.0718863, 0, 1, 2, 3, 4e-3, -5, 6}));
}

// OpenFOAM writes lists of up to ten entries on one line, with no space
// between the size and the parenthesis.
TEST_F(OpenFoamFieldFile, ReadsShortListsWrittenOnOneLine) {
  const fs::path p = write("p", vol_header("volScalarField", "p") +
                                    "dimensions [0 2 -2 0 0 0 0];\ninternalField   nonuniform "
                                    "List<scalar> 3(7.26677e-17 0.0667704 -0.180079);\n");
  EXPECT_EQ(read_internal_field(p, FieldType::scalar, 3),
            (std::vector<double>{7.26677e-17, 0.0667704, -0.180079}));
  const fs::path c = write("C", vol_header("volVectorField", "C") +
                                    "internalField nonuniform List<vector> 2((0.0166667 0.025 "
                                    "0.005) (0.05 0.025 0.005));\n");
  EXPECT_EQ(read_internal_field(c, FieldType::vector, 2),
            (std::vector<double>{0.0166667, 0.025, 0.005, 0.05, 0.025, 0.005}));
}

TEST_F(OpenFoamFieldFile, ExpandsAUniformInternalFieldToTheCellCount) {
  const fs::path alpha =
      write("alpha.water", vol_header("volScalarField", "alpha.water") +
                               "internalField   uniform 0.25;\n" + dam_break_boundary());
  EXPECT_EQ(read_internal_field(alpha, FieldType::scalar, 3), (std::vector<double>(3, 0.25)));
  const fs::path u =
      write("U", vol_header("volVectorField", "U") + "internalField   uniform (1 -2 3.5);\n");
  EXPECT_EQ(read_internal_field(u, FieldType::vector, 2),
            (std::vector<double>{1, -2, 3.5, 1, -2, 3.5}));
}

TEST_F(OpenFoamFieldFile, ExpandsTheCompactForm) {
  const fs::path p = write(
      "p", vol_header("volScalarField", "p") + "internalField nonuniform List<scalar> 4{-1.5};\n");
  EXPECT_EQ(read_internal_field(p, FieldType::scalar, 4), (std::vector<double>(4, -1.5)));
  const fs::path u = write("U", vol_header("volVectorField", "U") +
                                    "internalField nonuniform List<vector> 2 { ( 0 0 9 ) } ;\n");
  EXPECT_EQ(read_internal_field(u, FieldType::vector, 2), (std::vector<double>{0, 0, 9, 0, 0, 9}));
}

TEST_F(OpenFoamFieldFile, ToleratesCommentsAndAnyLayout) {
  const fs::path file =
      write("p",
            "// leading comment\r\nFoamFile /* inline */ { format ascii; class volScalarField;\r\n"
            "object p; note \"a { brace ; in a string\"; }\r\n"
            "#include \"initialConditions\"\r\n"
            "dimensions [0 2 -2 0 0 0 0]; // trailing\r\n"
            "boundaryField { wall { type fixedValue; value nonuniform List<scalar> 2(1 2); } }\r\n"
            "internalField\tnonuniform /* the type: */ List<scalar>\r\n  3 // size\r\n"
            "( 1.5 /* first */ 2.5\r\n// whole-line comment ( 9 9 )\r\n3.5)\r\n;\r\n");
  EXPECT_EQ(read_internal_field(file, FieldType::scalar, 3), (std::vector<double>{1.5, 2.5, 3.5}));
}

TEST_F(OpenFoamFieldFile, CountMismatchNamesFileLineAndCounts) {
  // The size is on line 18 of this layout.
  const fs::path file = write("p", vol_header("volScalarField", "p") +
                                       "dimensions      [1 -1 -2 0 0 0 0];\n\n\n"
                                       "internalField   nonuniform List<scalar> \n3\n(\n1\n2\n3\n)"
                                       "\n;\n");
  EXPECT_EQ(error_of([&] { read_internal_field(file, FieldType::scalar, 4); }),
            file.string() + ":18: expected 4 values in internalField, found 3");
}

TEST_F(OpenFoamFieldFile, TruncatedListNamesTheLineWhereItEnds) {
  const fs::path closed_early =
      write("p", "internalField nonuniform List<scalar>\n3\n(\n1\n2\n)\n;\n");
  EXPECT_EQ(error_of([&] { read_internal_field(closed_early, FieldType::scalar, 3); }),
            closed_early.string() + ":6: expected 3 values in internalField, found 2");
  const fs::path cut_off = write("U", "internalField nonuniform List<vector>\n2\n(\n(1 2 3)\n");
  EXPECT_EQ(error_of([&] { read_internal_field(cut_off, FieldType::vector, 2); }),
            cut_off.string() + ":5: expected 2 values in internalField, found 1");
  const fs::path half_vector =
      write("U", "internalField nonuniform List<vector>\n2\n(\n(1 2 3)\n(4 5");
  EXPECT_EQ(error_of([&] { read_internal_field(half_vector, FieldType::vector, 2); }),
            half_vector.string() +
                ":5: expected a vector (x y z) as value 2 of internalField, found the end of the "
                "file");
}

TEST_F(OpenFoamFieldFile, GarbageTokenNamesFileLineAndToken) {
  const fs::path file = write("p", "internalField nonuniform List<scalar>\n3\n(\n1\n2x\n3\n);\n");
  EXPECT_EQ(error_of([&] { read_internal_field(file, FieldType::scalar, 3); }),
            file.string() + ":5: expected a number as value 2 of internalField, found '2x'");
  const fs::path extra = write("q", "internalField nonuniform List<scalar> 2(1 2 3);\n");
  EXPECT_EQ(error_of([&] { read_internal_field(extra, FieldType::scalar, 2); }),
            extra.string() + ":1: expected ')' closing internalField after 2 values, found '3'");
  const fs::path macro = write("r", "internalField uniform $pressure;\n");
  EXPECT_EQ(
      error_of([&] { read_internal_field(macro, FieldType::scalar, 2); }),
      macro.string() + ":1: expected a number as value 1 of internalField, found '$pressure'");
}

TEST_F(OpenFoamFieldFile, WrongFieldTypeOrFormIsNamed) {
  const fs::path u = write("U", "internalField nonuniform List<vector> 1((1 2 3));\n");
  EXPECT_EQ(error_of([&] { read_internal_field(u, FieldType::scalar, 1); }),
            u.string() + ":1: expected List<scalar> in internalField, found 'List<vector>'");
  const fs::path p = write("p", "internalField 1.5;\n");
  EXPECT_EQ(error_of([&] { read_internal_field(p, FieldType::scalar, 1); }),
            p.string() + ":1: expected uniform or nonuniform in internalField, found '1.5'");
  const fs::path unended =
      write("unended", "FoamFile\n{\n    version 2.0\n}\ninternalField uniform 0;\n");
  EXPECT_EQ(error_of([&] { read_internal_field(unended, FieldType::scalar, 1); }),
            unended.string() + ":4: expected ';' ending the entry 'version', found '}'");
  const fs::path none =
      write("none", vol_header("volScalarField", "none") + "dimensions [0 0 0 0 0 0 0];\n");
  EXPECT_EQ(error_of([&] { read_internal_field(none, FieldType::scalar, 1); }),
            none.string() + ":15: expected an internalField entry, found the end of the file");
}

TEST_F(OpenFoamFieldFile, BinaryFilesAreRefused) {
  std::string header = vol_header("volScalarField", "p");
  header.replace(header.find("ascii"), 5, "binary");
  const fs::path file = write("p", header + "internalField uniform 0;\n");
  EXPECT_EQ(error_of([&] { read_internal_field(file, FieldType::scalar, 1); }),
            file.string() +
                ":7: expected format ascii, found 'binary' (the case must use writeFormat ascii)");
}

TEST_F(OpenFoamFieldFile, MissingFileIsNamed) {
  const std::string message =
      error_of([&] { read_internal_field(dir_ / "p", FieldType::scalar, 1); });
  EXPECT_EQ(message.rfind("cannot read OpenFOAM file '" + (dir_ / "p").string() + "'", 0), 0u)
      << message;
  write("U.gz", "compressed");
  EXPECT_NE(error_of([&] {
              read_field_list(dir_ / "U", FieldType::vector);
            }).find("writeCompression off"),
            std::string::npos);
}

TEST_F(OpenFoamFieldFile, NonFiniteValuesAreANumericalFailure) {
  const fs::path file = write("p", "internalField nonuniform List<scalar>\n2\n(\n1\n-nan\n)\n;\n");
  EXPECT_EQ(error_of([&] { read_internal_field(file, FieldType::scalar, 2); },
                     cosim::ExitCode::numerical_failure),
            file.string() + ":5: value 2 of internalField is not finite ('-nan')");
  const fs::path u = write("U", "internalField nonuniform List<vector> 2((1 2 3) (4 inf 6));\n");
  EXPECT_EQ(error_of([&] { read_internal_field(u, FieldType::vector, 2); },
                     cosim::ExitCode::numerical_failure),
            u.string() + ":1: value 2 of internalField is not finite ('(4 inf 6)')");
}

TEST_F(OpenFoamFieldFile, VolFieldRoundTripsToTheBit) {
  const std::vector<double> values{0.1,
                                   1.0 / 3.0,
                                   -0.0,
                                   std::numeric_limits<double>::denorm_min(),
                                   std::numeric_limits<double>::max(),
                                   -2.2250738585072014e-308,
                                   1e-05,
                                   123456789.123456789,
                                   -7.0};
  const fs::path scalar_file = dir_ / "p_rgh";
  write_vol_field(scalar_file, "0.05",
                  {.type = FieldType::scalar,
                   .dimensions = "[1 -1 -2 0 0 0 0]",
                   .values = values,
                   .boundary_field = walls_zero_gradient});
  EXPECT_EQ(bits_of(read_internal_field(scalar_file, FieldType::scalar, values.size())),
            bits_of(values));
  const fs::path vector_file = dir_ / "U";
  write_vol_field(vector_file, "0.05",
                  {.type = FieldType::vector,
                   .dimensions = "[0 1 -1 0 0 0 0]",
                   .values = values,
                   .boundary_field = "    walls\n    {\n        type noSlip;\n    }"});
  EXPECT_EQ(bits_of(read_internal_field(vector_file, FieldType::vector, 3)), bits_of(values));
}

TEST_F(OpenFoamFieldFile, VolFieldFileHasHeaderDimensionsAndBoundaryVerbatim) {
  const std::vector<double> values{1.5, 0, -2};
  const fs::path file = dir_ / "U";
  write_vol_field(file, "0.05",
                  {.type = FieldType::vector,
                   .dimensions = "[0 1 -1 0 0 0 0]",
                   .values = values,
                   .boundary_field = "    walls\n    {\n        type noSlip;\n    }"});
  EXPECT_EQ(read_text(file),
            foam_file_header({.class_name = "volVectorField", .location = "0.05", .object = "U"}) +
                "dimensions      [0 1 -1 0 0 0 0];\n\n"
                "internalField   nonuniform List<vector>\n1\n(\n(1.5 0 -2)\n)\n;\n\n"
                "boundaryField\n{\n    walls\n    {\n        type noSlip;\n    }\n}\n");
  EXPECT_FALSE(fs::exists(dir_ / ".U.tmp"));
}

TEST_F(OpenFoamFieldFile, HeaderBlockHasOptionalLocation) {
  EXPECT_EQ(
      foam_file_header({.class_name = "dictionary", .location = "system", .object = "controlDict"}),
      "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       dictionary;\n"
      "    location    \"system\";\n    object      controlDict;\n}\n\n");
  EXPECT_EQ(
      foam_file_header({.class_name = "labelField", .location = "", .object = "origId"}),
      "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       labelField;\n"
      "    object      origId;\n}\n\n");
}

TEST_F(OpenFoamFieldFile, NonFiniteValuesAreNotWritten) {
  const std::vector<double> values{1.0, std::nan(""), 3.0};
  const fs::path file = dir_ / "U";
  const std::string message = error_of(
      [&] { write_field_list(file, "0.05/lagrangian/kinematicCloud", FieldType::scalar, values); },
      cosim::ExitCode::numerical_failure);
  EXPECT_NE(message.find("value 1 is not finite"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(file));
  EXPECT_THROW(write_vol_field(file, "0",
                               {.type = FieldType::vector,
                                .dimensions = "[0 1 -1 0 0 0 0]",
                                .values = {values.data(), 2},
                                .boundary_field = walls_zero_gradient}),
               std::invalid_argument);
}

// Lagrangian cloud files as MPPICFoam writes them (class scalarField,
// vectorField, labelField; constant lists in the compact form).
TEST_F(OpenFoamFieldFile, ReadsLagrangianListFiles) {
  const fs::path u = write("U", vol_header("vectorField", "U") +
                                    "\n3\n(\n(0 0 -0.0019824504)\n(0 0 -0.0020019699)\n(1 2 3)\n)"
                                    "\n\n\n// ***** //\n");
  EXPECT_EQ(read_field_list(u, FieldType::vector, 3),
            (std::vector<double>{0, 0, -0.0019824504, 0, 0, -0.0020019699, 1, 2, 3}));
  const fs::path u_turb = write("UTurb", vol_header("vectorField", "UTurb") + "2873{(0 0 0)}\n");
  EXPECT_EQ(read_field_list(u_turb, FieldType::vector), std::vector<double>(3 * 2873, 0.0));
  const fs::path d = write("d", vol_header("scalarField", "d") + "2873{0.0003}\n\n// * //\n");
  EXPECT_EQ(read_field_list(d, FieldType::scalar, 2873), std::vector<double>(2873, 0.0003));
  const fs::path type_id = write("typeId", vol_header("labelField", "typeId") + "4{-1}\n");
  EXPECT_EQ(read_label_list(type_id), (std::vector<std::int64_t>(4, -1)));
  const fs::path empty = write("origId", vol_header("labelField", "origId") + "0()\n");
  EXPECT_TRUE(read_label_list(empty, 0).empty());
  const fs::path bare = write("cellProcAddressing", "3\n(\n0\n7\n2\n)\n");
  EXPECT_EQ(read_label_list(bare), (std::vector<std::int64_t>{0, 7, 2}));
}

TEST_F(OpenFoamFieldFile, ListFileErrorsNameFileAndLine) {
  const fs::path d = write("d", vol_header("scalarField", "d") + "2873{0.0003}\n");
  EXPECT_EQ(error_of([&] { read_field_list(d, FieldType::scalar, 2872); }),
            d.string() + ":14: expected 2872 values in the list, found 2873");
  const fs::path label = write("origId", "3\n(\n0\n1.5\n2\n)\n");
  EXPECT_EQ(error_of([&] { read_label_list(label); }),
            label.string() + ":4: expected a label as value 2 of the list, found '1.5'");
  const fs::path trailing = write("rho", "2(1 2)\n3\n");
  EXPECT_EQ(error_of([&] { read_field_list(trailing, FieldType::scalar); }),
            trailing.string() + ":2: expected the end of the file after the list, found '3'");
  const fs::path corrupt_size = write("nParticle", "999999999999(1 2)\n");
  EXPECT_EQ(error_of([&] { read_field_list(corrupt_size, FieldType::scalar); }),
            corrupt_size.string() + ":1: expected 999999999999 values in the list, found 2");
}

TEST_F(OpenFoamFieldFile, ListsRoundTripToTheBit) {
  const std::vector<double> values{0.1, -1e-300, 2.5e7, 1.0 / 7.0, -0.0, 0.30000000000000004};
  const fs::path scalars = dir_ / "nParticle";
  write_field_list(scalars, "0.05/lagrangian/kinematicCloud", FieldType::scalar, values);
  EXPECT_EQ(bits_of(read_field_list(scalars, FieldType::scalar, 6)), bits_of(values));
  EXPECT_NE(read_text(scalars).find("class       scalarField;"), std::string::npos);
  const fs::path vectors = dir_ / "U";
  write_field_list(vectors, "0.05/lagrangian/kinematicCloud", FieldType::vector, values);
  EXPECT_EQ(bits_of(read_field_list(vectors, FieldType::vector, 2)), bits_of(values));
  EXPECT_NE(read_text(vectors).find("class       vectorField;"), std::string::npos);
  const std::vector<std::int64_t> labels{0, -1, 2147483647, 5};
  const fs::path label_file = dir_ / "origId";
  write_label_list(label_file, "0.05/lagrangian/kinematicCloud", labels);
  EXPECT_EQ(read_label_list(label_file, 4), labels);
  EXPECT_NE(read_text(label_file).find("class       labelField;"), std::string::npos);
}

TEST_F(OpenFoamFieldFile, PositionsHoldCoordinatesAndTheCellOfEachParcel) {
  const std::vector<double> xyz{0.1, 0.2, 0.3, -1, 0, 2.5};
  const std::vector<std::int64_t> cells{24, 33};
  const fs::path file = dir_ / "positions";
  write_parcel_positions(file, "0.05/lagrangian/kinematicCloud", "basicKinematicMPPICParcel", xyz,
                         cells);
  EXPECT_EQ(read_text(file),
            foam_file_header({.class_name = "Cloud<basicKinematicMPPICParcel>",
                              .location = "0.05/lagrangian/kinematicCloud",
                              .object = "positions"}) +
                "2\n(\n(0.10000000000000001 0.20000000000000001 0.29999999999999999) 24\n"
                "(-1 0 2.5) 33\n)\n");
  EXPECT_THROW(
      write_parcel_positions(file, "", "basicKinematicMPPICParcel", xyz, {cells.data(), 1}),
      std::invalid_argument);
}

// A large field, as the adapter reads every window, comes back bit for bit.
TEST_F(OpenFoamFieldFile, ReadsTwentyThousandCellsBitForBit) {
  constexpr std::size_t cells = 20000;
  std::vector<double> values(3 * cells);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = std::sin(0.37 * static_cast<double>(i)) * 1e3;
  const fs::path file = dir_ / "U";
  write_vol_field(file, "0.05",
                  {.type = FieldType::vector,
                   .dimensions = "[0 1 -1 0 0 0 0]",
                   .values = values,
                   .boundary_field = walls_zero_gradient});
  const fs::path p = dir_ / "p";
  write_vol_field(p, "0.05",
                  {.type = FieldType::scalar,
                   .dimensions = "[1 -1 -2 0 0 0 0]",
                   .values = {values.data(), cells},
                   .boundary_field = walls_zero_gradient});
  const std::vector<double> read_vectors = read_internal_field(file, FieldType::vector, cells);
  const std::vector<double> read_scalars = read_internal_field(p, FieldType::scalar, cells);
  EXPECT_EQ(bits_of(read_vectors), bits_of(values));
  EXPECT_EQ(bits_of(read_scalars),
            bits_of(std::vector<double>(values.begin(), values.begin() + cells)));
}

}  // namespace
}  // namespace openfoam
