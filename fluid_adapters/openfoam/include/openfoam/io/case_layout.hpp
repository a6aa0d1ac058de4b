#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "openfoam/cloud/soil_cloud.hpp"
#include "openfoam/foam/field_file.hpp"
#include "openfoam/foam/time_directories.hpp"
#include "openfoam/io/foam_fields.hpp"

namespace openfoam {

// Where a run's time directories live: the case itself when OpenFOAM runs
// serial, or, decomposed once at the start (decomposePar), each
// processor<N>/ directory with its own cells. A decomposed case is never
// reconstructed: the adapter writes each processor's parcels with its local
// cell labels and gathers the fields it reads back through
// processor<N>/constant/polyMesh/cellProcAddressing (local cell -> cell of
// the whole mesh).
class CaseLayout {
 public:
  // Serial: `processes` = 1. Decomposed: reads the processors' addressing
  // (run decomposePar first) and checks it covers each of `cells` once.
  CaseLayout(std::filesystem::path case_dir, int processes, std::size_t cells);

  int processes() const { return processes_; }
  // The latest time directory the solver wrote (processor0's when decomposed).
  std::optional<TimeDirectory> latest() const;
  // The fields at time `name`, over the whole mesh.
  FoamFields read(const std::string& name, int dim) const;
  // One scalar field at time `name`, over the whole mesh.
  std::vector<double> read_scalar(const std::string& name, const std::string& field) const;
  // One vector field (or a cloud's DimensionedField, e.g. kinematicCloud:UTrans) at time
  // `name`, over the whole mesh: x, y, z per cell.
  std::vector<double> read_vector(const std::string& name, const std::string& field) const;
  // Whether time `name` holds `field` (processor0's when decomposed).
  bool has(const std::string& name, const std::string& field) const;
  // The time directory of `time` (to `tolerance`), none when absent.
  std::optional<TimeDirectory> at(double time, double tolerance) const;
  // The window's parcels (cells of the whole mesh) into time `name`.
  void write_cloud(const std::string& name, const SoilParcels& parcels,
                   double parcel_density) const;
  // A scalar vol field of the whole mesh (zero gradient on every patch,
  // constraint patches as their type) written into time `name`.
  void write_scalar_field(const std::string& name, const std::string& field,
                          const std::string& dimensions, std::span<const double> values) const;
  // Removes time `name` (every processor's).
  void remove_time(const std::string& name) const;
  // Removes every time directory but `keep`.
  void remove_times_except(std::span<const std::string> keep) const;
  // Time `name` of every processor copied into `into`, as
  // <into>/<root>/<name> (root "." serial, processor<N> decomposed): a
  // checkpoint's copy of the case; copy_times_in() puts such a copy back.
  void copy_time_out(const std::string& name, const std::filesystem::path& into) const;
  void copy_times_in(const std::filesystem::path& from) const;

 private:
  std::vector<std::filesystem::path> roots() const;
  std::vector<double> read_gathered(const std::string& name, const std::string& field,
                                    FieldType type) const;

  std::filesystem::path case_dir_;
  int processes_;
  std::size_t cells_;
  std::vector<std::vector<std::int64_t>> addressing_;  // per processor: its cells' global labels
  std::vector<std::int64_t> owner_;                    // per global cell: processor
  std::vector<std::int64_t> local_;                    // per global cell: its local label
};

}  // namespace openfoam
