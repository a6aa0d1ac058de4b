#include "openfoam/cloud/soil_cloud.hpp"

#include <fmt/format.h>

#include <string>

#include "cosim/io/files.hpp"
#include "openfoam/foam/field_file.hpp"
#include "openfoam/foam/foam_file_header.hpp"

namespace openfoam {

namespace fs = std::filesystem;

void SoilParcels::clear() {
  position.clear();
  cell.clear();
  velocity.clear();
  diameter.clear();
  grains.clear();
}

void SoilParcels::add(const double* centre, std::int64_t cell_index, const double* u, double d,
                      double grain_count) {
  position.insert(position.end(), centre, centre + 3);
  cell.push_back(cell_index);
  velocity.insert(velocity.end(), u, u + 3);
  diameter.push_back(d);
  grains.push_back(grain_count);
}

void write_soil_cloud(const fs::path& time_dir, std::string_view time_name,
                      const SoilParcels& parcels, double parcel_density) {
  const fs::path cloud = time_dir / "lagrangian" / cloud_name;
  const fs::path properties = time_dir / "uniform" / "lagrangian" / cloud_name;
  if (parcels.size() == 0) {
    fs::remove_all(cloud);
    fs::remove_all(properties);
    return;
  }
  fs::create_directories(cloud);
  fs::create_directories(properties);
  const std::string location = fmt::format("{}/lagrangian/{}", time_name, cloud_name);
  const std::size_t n = parcels.size();
  const auto scalars = [&](const char* name, const std::vector<double>& values) {
    write_field_list(cloud / name, location, FieldType::scalar, values);
  };
  const auto vectors = [&](const char* name, const std::vector<double>& values) {
    write_field_list(cloud / name, location, FieldType::vector, values);
  };
  const auto labels = [&](const char* name, const std::vector<std::int64_t>& values) {
    write_label_list(cloud / name, location, values);
  };
  write_parcel_positions(cloud / "positions", location, parcel_class, parcels.position,
                         parcels.cell);
  fs::remove(cloud / "coordinates");
  vectors("U", parcels.velocity);
  scalars("d", parcels.diameter);
  scalars("dTarget", parcels.diameter);
  scalars("nParticle", parcels.grains);
  scalars("rho", std::vector<double>(n, parcel_density));
  scalars("age", std::vector<double>(n, 0.0));
  scalars("tTurb", std::vector<double>(n, 0.0));
  const std::vector<double> zero_vectors(3 * n, 0.0);
  vectors("UTurb", zero_vectors);
  vectors("UCorrect", zero_vectors);
  labels("active", std::vector<std::int64_t>(n, 1));
  labels("typeId", std::vector<std::int64_t>(n, -1));
  std::vector<std::int64_t> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<std::int64_t>(i);
  labels("origId", ids);
  labels("origProcId", std::vector<std::int64_t>(n, 0));
  cosim::write_file_atomically(
      properties / "cloudProperties",
      foam_file_header({"dictionary",
                        fmt::format("{}/uniform/lagrangian/{}", time_name, cloud_name),
                        "cloudProperties"}) +
          "geometry positions;\n");
}

}  // namespace openfoam
