#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

// OpenFOAM's ASCII field files: the vol fields of a time directory (p, U,
// alpha.water, C, V, ...) and the plain lists of a lagrangian cloud
// (U, d, nParticle, positions, ...) or of decomposePar (cellProcAddressing).
// Values are flattened: a vector field holds x, y, z per entry.
namespace openfoam {

enum class FieldType { scalar, vector };

constexpr std::size_t components(FieldType type) {
  return type == FieldType::vector ? 3 : 1;
}

// Reading files OpenFOAM wrote. A file that is missing, binary, or cannot be
// parsed throws cosim::Error(participant_failed) reading
// `<file>:<line>: expected <what>, found <what>`; a NaN or infinite value
// throws cosim::NumericalError naming file and line.

// The internalField of a vol<Type>Field file, `cells` entries: `uniform <v>`
// (expanded), `nonuniform List<Type> N (...)` or `N{v}`. Whatever follows it
// (boundaryField) is not read. A DimensionedField file (a cloud's
// kinematicCloud:UTrans) has its values under `value` instead.
std::vector<double> read_internal_field(const std::filesystem::path& file, FieldType type,
                                        std::size_t cells);

// The one list, `N (...)` or `N{v}`, after the header of a list file. When
// `entries` is given, N must equal it.
std::vector<double> read_field_list(const std::filesystem::path& file, FieldType type,
                                    std::optional<std::size_t> entries = std::nullopt);
std::vector<std::int64_t> read_label_list(const std::filesystem::path& file,
                                          std::optional<std::size_t> entries = std::nullopt);

// Writing, atomically (tmp + rename). Values get 17 significant digits, so
// they read back bit for bit; a non-finite value throws cosim::NumericalError
// and nothing is written. `location` is the header's location, e.g. "0.05"
// (empty: none); the header's object is the file's name.

struct VolField {
  FieldType type = FieldType::scalar;
  std::string dimensions;          // exponents of kg m s K mol A cd, e.g. "[0 1 -1 0 0 0 0]"
  std::span<const double> values;  // one entry per cell
  std::string boundary_field;      // the patch entries between boundaryField's braces, verbatim
};

void write_vol_field(const std::filesystem::path& file, std::string_view location,
                     const VolField& field);

// A lagrangian per-parcel field: class scalarField / vectorField / labelField.
void write_field_list(const std::filesystem::path& file, std::string_view location, FieldType type,
                      std::span<const double> values);
void write_label_list(const std::filesystem::path& file, std::string_view location,
                      std::span<const std::int64_t> labels);

// A cloud's `positions`, class Cloud<parcel_type>: `N ( (x y z) celli ... )`
// with celli the cell holding the parcel.
void write_parcel_positions(const std::filesystem::path& file, std::string_view location,
                            std::string_view parcel_type, std::span<const double> xyz,
                            std::span<const std::int64_t> cells);

}  // namespace openfoam
