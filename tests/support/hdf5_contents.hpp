#pragma once

#include <hdf5.h>

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

// What an HDF5 file holds, to compare the files of two runs: the object
// headers also store when each object was made, so the bytes of two files
// with the same contents differ.
namespace cosim::testing {

namespace hdf5_contents_detail {

struct Visit {
  std::map<std::string, std::string> contents;
  std::string object;  // the path of the object being read
};

inline std::string dimensions(hid_t space) {
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  std::string text = "[";
  for (const hsize_t n : dims) text += std::to_string(n) + ",";
  return text + "]";
}

inline std::string value_buffer(hid_t type, hid_t space) {
  const auto count = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  return std::string(count * H5Tget_size(type), '\0');
}

inline herr_t add_attribute(hid_t owner, const char* name, const H5A_info_t*, void* data) {
  auto& visit = *static_cast<Visit*>(data);
  const hid_t attribute = H5Aopen(owner, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(attribute);
  const hid_t space = H5Aget_space(attribute);
  std::string values = value_buffer(type, space);
  H5Aread(attribute, type, values.data());
  visit.contents[visit.object + "@" + name] = dimensions(space) + values;
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(attribute);
  return 0;
}

inline void add_attributes(hid_t object, Visit& visit) {
  H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, add_attribute, &visit);
}

inline herr_t add_object(hid_t group, const char* name, const H5L_info_t*, void* data) {
  auto& visit = *static_cast<Visit*>(data);
  const hid_t object = H5Oopen(group, name, H5P_DEFAULT);
  if (object < 0) return -1;
  visit.object = std::string("/") + name;
  if (H5Iget_type(object) == H5I_DATASET) {
    const hid_t type = H5Dget_type(object);
    const hid_t space = H5Dget_space(object);
    std::string values = value_buffer(type, space);
    if (!values.empty()) H5Dread(object, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    visit.contents[visit.object] = dimensions(space) + values;
    H5Sclose(space);
    H5Tclose(type);
  }
  add_attributes(object, visit);
  H5Oclose(object);
  return 0;
}

}  // namespace hdf5_contents_detail

// Every dataset and attribute by path ("/fields/h", "/fields/h@unit", and
// "@time" for the root group's): its dimensions and the bytes of its values
// in the file's own type.
inline std::map<std::string, std::string> hdf5_contents(const std::filesystem::path& path) {
  namespace detail = hdf5_contents_detail;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("cannot open " + path.string());
  detail::Visit visit;
  detail::add_attributes(file, visit);
  const herr_t visited = H5Lvisit(file, H5_INDEX_NAME, H5_ITER_INC, detail::add_object, &visit);
  H5Fclose(file);
  if (visited < 0) throw std::runtime_error("cannot read every object of " + path.string());
  return visit.contents;
}

}  // namespace cosim::testing
