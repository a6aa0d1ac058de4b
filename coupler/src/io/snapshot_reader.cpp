#include "cosim/io/snapshot_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "cosim/error.hpp"
#include "hdf5_file.hpp"

namespace cosim {

namespace fs = std::filesystem;

namespace {

bool has_object(hid_t file, const std::string& path) {
  std::size_t slash = 0;
  while ((slash = path.find('/', slash + 1)) != std::string::npos)
    if (H5Lexists(file, path.substr(0, slash).c_str(), H5P_DEFAULT) <= 0) return false;
  return H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0;
}

hdf5::FileHandle open_file(const fs::path& path) {
  hdf5::silence_error_printing();
  return hdf5::FileHandle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                          "cannot open " + path.string());
}

SnapshotReader::Field read_dataset(hid_t file, const std::string& path, const fs::path& name) {
  hdf5::DatasetHandle set(H5Dopen2(file, path.c_str(), H5P_DEFAULT),
                          fmt::format("{}: no dataset {}", name.string(), path));
  hdf5::DataspaceHandle space(H5Dget_space(set.get()), "dataspace of " + path);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  std::size_t total = 1;
  for (auto d : dims) total *= static_cast<std::size_t>(d);
  SnapshotReader::Field f;
  f.values.resize(total);
  if (total > 0 &&
      H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, f.values.data()) < 0)
    hdf5::fail(fmt::format("{}: reading {}", name.string(), path));
  return f;
}

double time_attribute(hid_t file, const fs::path& name) {
  hdf5::AttributeHandle a(H5Aopen(file, "time", H5P_DEFAULT),
                          name.string() + ": no 'time' attribute");
  double t = 0.0;
  if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, &t) < 0) hdf5::fail(name.string() + ": reading time");
  return t;
}

// The text between `open` (after `from`) and the next `close`, or nothing.
std::optional<std::string> between(const std::string& s, const std::string& open,
                                   const std::string& close, std::size_t& from) {
  const auto start = s.find(open, from);
  if (start == std::string::npos) return std::nullopt;
  const auto end = s.find(close, start + open.size());
  if (end == std::string::npos) return std::nullopt;
  from = end + close.size();
  return s.substr(start + open.size(), end - start - open.size());
}

template <class T>
std::vector<T> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<T> out;
  for (T x{}; in >> x;) out.push_back(x);
  return out;
}

// The grid of a CoRectMesh index: the topology's node counts and the first
// two XML data items, origin and spacing, all slowest direction first.
std::optional<SnapshotReader::Grid> grid_of_index(const fs::path& xdmf) {
  std::ifstream in(xdmf);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  SnapshotReader::Grid g;
  std::size_t at = s.find("DCoRectMesh\"");
  if (at == std::string::npos || at == 0) return std::nullopt;
  g.dimension = s[at - 1] == '3' ? 3 : 2;
  const auto nodes = between(s, "Dimensions=\"", "\"", at);
  const auto origin = between(s, "<DataItem Format=\"XML\"", "</DataItem>", at);
  const auto spacing = between(s, "<DataItem Format=\"XML\"", "</DataItem>", at);
  if (!nodes || !origin || !spacing) return std::nullopt;
  const auto counts = numbers<int>(*nodes);
  const auto o = numbers<double>(origin->substr(origin->find('>') + 1));
  const auto h = numbers<double>(spacing->substr(spacing->find('>') + 1));
  const auto dim = static_cast<std::size_t>(g.dimension);
  if (counts.size() != dim || o.size() != dim || h.size() != dim) return std::nullopt;
  for (std::size_t d = 0; d < dim; ++d) {
    const std::size_t slow = dim - 1 - d;
    g.cells[d] = counts[slow] - 1;
    g.origin[d] = o[slow];
    g.spacing[d] = h[slow];
  }
  return g;
}

// `<base>_<six digits>.h5`.
bool is_snapshot_name(const std::string& file, const std::string& base) {
  const std::string suffix = ".h5";
  if (file.size() != base.size() + 1 + 6 + suffix.size() || file.rfind(base + "_", 0) != 0 ||
      file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  return std::all_of(file.begin() + static_cast<std::ptrdiff_t>(base.size() + 1),
                     file.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}

// Cell centres of a line (2-node segments) or the points of a cloud.
std::vector<std::array<double, 3>> element_positions(hid_t file, const fs::path& name) {
  const auto xyz = read_dataset(file, "geometry/xyz", name);
  const std::size_t nodes = xyz.values.size() / 3;
  std::vector<std::array<double, 3>> points(nodes);
  for (std::size_t n = 0; n < nodes; ++n)
    points[n] = {xyz.values[3 * n], xyz.values[3 * n + 1], xyz.values[3 * n + 2]};
  if (!has_object(file, "topology/connectivity")) return points;
  hdf5::DatasetHandle set(H5Dopen2(file, "topology/connectivity", H5P_DEFAULT), "connectivity");
  hdf5::DataspaceHandle space(H5Dget_space(set.get()), "connectivity");
  if (H5Sget_simple_extent_ndims(space.get()) != 2) return points;  // a cloud: one node each
  const auto c = read_dataset(file, "topology/connectivity", name);
  std::vector<std::array<double, 3>> centres(c.values.size() / 2);
  for (std::size_t e = 0; e < centres.size(); ++e) {
    const auto& a = points[static_cast<std::size_t>(c.values[2 * e])];
    const auto& b = points[static_cast<std::size_t>(c.values[2 * e + 1])];
    centres[e] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
  }
  return centres;
}

}  // namespace

SnapshotReader::SnapshotReader(fs::path directory, std::string base)
    : directory_(std::move(directory)), base_(std::move(base)) {
  std::map<std::string, fs::path> found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory_, ec)) {
    const std::string file = entry.path().filename().string();
    if (is_snapshot_name(file, base_)) found[file] = entry.path();
  }
  if (found.empty())
    throw Error(ExitCode::bad_input, fmt::format("{}: no snapshots {}_*.h5 (was the output "
                                                 "interval set?)",
                                                 directory_.string(), base_));
  for (const auto& [file, path] : found) {
    const auto f = open_file(path);
    times_.push_back(time_attribute(f.get(), path));
    files_.push_back(path);
  }
  grid_ = grid_of_index(directory_ / (base_ + ".xdmf"));
  const fs::path mesh = directory_ / (base_ + "_mesh.h5");
  if (!grid_ && fs::exists(mesh)) {
    const auto f = open_file(mesh);
    mesh_positions_ = element_positions(f.get(), mesh);
  }
}

std::size_t SnapshotReader::nearest(double time) const {
  std::size_t best = 0;
  for (std::size_t i = 1; i < times_.size(); ++i)
    if (std::abs(times_[i] - time) < std::abs(times_[best] - time)) best = i;
  return best;
}

bool SnapshotReader::has_field(std::size_t snapshot, const std::string& name) const {
  const auto f = open_file(files_.at(snapshot));
  return has_object(f.get(), "fields/" + name);
}

SnapshotReader::Field SnapshotReader::field(std::size_t snapshot, const std::string& name) const {
  const fs::path& path = files_.at(snapshot);
  const auto f = open_file(path);
  if (!has_object(f.get(), "fields/" + name))
    throw Error(ExitCode::bad_input, fmt::format("{}: no field '{}'", path.string(), name));
  Field out = read_dataset(f.get(), "fields/" + name, path);
  hdf5::DatasetHandle set(H5Dopen2(f.get(), ("fields/" + name).c_str(), H5P_DEFAULT), name);
  hdf5::DataspaceHandle space(H5Dget_space(set.get()), name);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  // Grids store (nz,) ny, nx [, c]; lines and clouds n [, c].
  const int spatial = grid_ ? grid_->dimension : 1;
  out.components = rank > spatial ? static_cast<int>(dims.back()) : 1;
  return out;
}

std::vector<std::array<double, 3>> SnapshotReader::positions(std::size_t snapshot) const {
  if (grid_) {
    const Grid& g = *grid_;
    std::vector<std::array<double, 3>> centres;
    centres.reserve(static_cast<std::size_t>(g.cells[0] * g.cells[1] * g.cells[2]));
    for (int k = 0; k < g.cells[2]; ++k)
      for (int j = 0; j < g.cells[1]; ++j)
        for (int i = 0; i < g.cells[0]; ++i)
          centres.push_back({g.origin[0] + (i + 0.5) * g.spacing[0],
                             g.origin[1] + (j + 0.5) * g.spacing[1],
                             g.dimension == 3 ? g.origin[2] + (k + 0.5) * g.spacing[2] : 0.0});
    return centres;
  }
  const auto f = open_file(files_.at(snapshot));
  if (has_object(f.get(), "geometry/xyz")) return element_positions(f.get(), files_[snapshot]);
  return mesh_positions_;
}

std::size_t SnapshotReader::element_at(std::size_t snapshot,
                                       const std::array<double, 3>& point) const {
  if (grid_) {
    const Grid& g = *grid_;
    std::array<int, 3> index{0, 0, 0};
    for (std::size_t d = 0; d < static_cast<std::size_t>(g.dimension); ++d) {
      const int i = static_cast<int>(std::floor((point[d] - g.origin[d]) / g.spacing[d]));
      index[d] = std::clamp(i, 0, g.cells[d] - 1);
    }
    return static_cast<std::size_t>((index[2] * g.cells[1] + index[1]) * g.cells[0] + index[0]);
  }
  const auto centres = positions(snapshot);
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < centres.size(); ++e) {
    double d2 = 0.0;
    for (std::size_t d = 0; d < 3; ++d)
      d2 += (centres[e][d] - point[d]) * (centres[e][d] - point[d]);
    if (d2 < best_distance) {
      best_distance = d2;
      best = e;
    }
  }
  return best;
}

}  // namespace cosim
