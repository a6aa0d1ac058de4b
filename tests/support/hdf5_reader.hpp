#pragma once

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

// Reads back what the snapshot writer stored, with the HDF5 C API directly.
namespace cosim::testing {

template <class T>
struct Dataset {
  std::vector<hsize_t> dims;
  std::vector<T> values;
};

class Hdf5Reader {
 public:
  explicit Hdf5Reader(const std::filesystem::path& path)
      : file_(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {
    if (file_ < 0) throw std::runtime_error("cannot open " + path.string());
  }
  ~Hdf5Reader() { H5Fclose(file_); }
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  bool has(const std::string& path) const {
    return H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0;
  }

  std::vector<hsize_t> dims(const std::string& path) const {
    const hid_t set = open(path);
    const hid_t space = H5Dget_space(set);
    std::vector<hsize_t> d(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, d.data(), nullptr);
    H5Sclose(space);
    H5Dclose(set);
    return d;
  }

  Dataset<double> doubles(const std::string& path) const {
    return read<double>(path, H5T_NATIVE_DOUBLE);
  }
  Dataset<std::int64_t> integers(const std::string& path) const {
    return read<std::int64_t>(path, H5T_NATIVE_INT64);
  }

  double root_double(const std::string& name) const {
    double value = 0.0;
    const hid_t attribute = H5Aopen(file_, name.c_str(), H5P_DEFAULT);
    if (attribute < 0) throw std::runtime_error("no attribute " + name);
    H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
    H5Aclose(attribute);
    return value;
  }

  std::string string_attribute(const std::string& object, const std::string& name) const {
    const hid_t attribute =
        H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (attribute < 0) throw std::runtime_error("no attribute " + name + " on " + object);
    const hid_t type = H5Aget_type(attribute);
    std::string value(H5Tget_size(type), '\0');
    H5Aread(attribute, type, value.data());
    H5Tclose(type);
    H5Aclose(attribute);
    return value;
  }

 private:
  hid_t open(const std::string& path) const {
    const hid_t set = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    if (set < 0) throw std::runtime_error("no dataset " + path);
    return set;
  }
  template <class T>
  Dataset<T> read(const std::string& path, hid_t memory_type) const {
    Dataset<T> d;
    d.dims = dims(path);
    std::size_t count = 1;
    for (const hsize_t n : d.dims) count *= n;
    d.values.resize(count);
    const hid_t set = open(path);
    if (count > 0) H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.values.data());
    H5Dclose(set);
    return d;
  }

  hid_t file_;
};

}  // namespace cosim::testing
