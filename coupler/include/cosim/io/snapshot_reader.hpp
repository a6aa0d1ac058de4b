#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cosim {

// Reads back the snapshots a SnapshotWriter left in a directory
// (`<base>_<step>.h5` with their `<base>.xdmf` index and, for lines and
// clouds, `<base>_mesh.h5`), for post-processing such as `cosim bench`.
// Element positions are the cell centres of grids and lines, or the points
// of clouds and particles (a snapshot's own geometry when it has one).
class SnapshotReader {
 public:
  struct Field {
    std::vector<double> values;  // element-major
    int components = 1;
    double at(std::size_t element, int component = 0) const {
      return values[element * static_cast<std::size_t>(components) +
                    static_cast<std::size_t>(component)];
    }
  };

  // A uniform grid's layout, fastest direction first.
  struct Grid {
    int dimension = 0;
    std::array<double, 3> origin{};
    std::array<double, 3> spacing{};
    std::array<int, 3> cells{1, 1, 1};
  };

  // Throws Error naming the directory when it holds no `<base>_*.h5`.
  SnapshotReader(std::filesystem::path directory, std::string base);

  const std::vector<double>& times() const { return times_; }
  std::size_t count() const { return times_.size(); }
  std::size_t nearest(double time) const;

  bool has_field(std::size_t snapshot, const std::string& name) const;
  // Throws Error naming the file and field when it is missing.
  Field field(std::size_t snapshot, const std::string& name) const;
  std::vector<std::array<double, 3>> positions(std::size_t snapshot) const;
  // Set for uniform grids (from the XDMF index).
  const std::optional<Grid>& grid() const { return grid_; }

  // The element nearest to a point (a grid's cell containing it, clamped).
  std::size_t element_at(std::size_t snapshot, const std::array<double, 3>& point) const;

 private:
  std::filesystem::path directory_;
  std::string base_;
  std::vector<double> times_;
  std::vector<std::filesystem::path> files_;
  std::optional<Grid> grid_;
  std::vector<std::array<double, 3>> mesh_positions_;  // lines and clouds written once
};

}  // namespace cosim
