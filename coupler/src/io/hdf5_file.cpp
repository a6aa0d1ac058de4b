#include "hdf5_file.hpp"

#include "cosim/error.hpp"

namespace cosim::hdf5 {

namespace {

herr_t collect_message(unsigned /*depth*/, const H5E_error2_t* entry, void* messages) {
  auto& text = *static_cast<std::string*>(messages);
  if (!text.empty()) text += "; ";
  text += entry->func_name != nullptr ? entry->func_name : "?";
  text += ": ";
  std::string description = entry->desc != nullptr ? entry->desc : "(no description)";
  for (char& c : description)
    if (c == '\n' || c == '\t') c = ' ';
  text += description;
  return 0;
}

}  // namespace

void silence_error_printing() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

void fail(const std::string& what) {
  std::string messages;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect_message, &messages);
  H5Eclear2(H5E_DEFAULT);
  throw Error(ExitCode::bad_input,
              "HDF5: " + what + (messages.empty() ? std::string() : ": " + messages));
}

OutputFile::OutputFile(const std::filesystem::path& path)
    : path_(path.string()),
      file_(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
            "cannot create '" + path_ + "'") {}

void OutputFile::write(const std::string& dataset, std::span<const hsize_t> dims,
                       std::span<const double> values, std::string_view unit) {
  write_raw(dataset, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(), values.size(), unit);
}

void OutputFile::write(const std::string& dataset, std::span<const hsize_t> dims,
                       std::span<const std::int64_t> values) {
  write_raw(dataset, dims, H5T_STD_I64LE, H5T_NATIVE_INT64, values.data(), values.size(), {});
}

void OutputFile::write_raw(const std::string& dataset, std::span<const hsize_t> dims,
                           hid_t file_type, hid_t memory_type, const void* values,
                           std::size_t count, std::string_view unit) {
  const std::string where = "'" + path_ + ":/" + dataset + "'";
  hsize_t expected = 1;
  for (const hsize_t d : dims) expected *= d;
  if (expected != count)
    throw Error(ExitCode::bad_input, "HDF5: " + where + ": " + std::to_string(count) +
                                         " values for a dataspace of " + std::to_string(expected));
  const PropertyListHandle link_properties(H5Pcreate(H5P_LINK_CREATE),
                                           "link properties for " + where);
  if (H5Pset_create_intermediate_group(link_properties.get(), 1) < 0)
    fail("intermediate groups for " + where);
  const DataspaceHandle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                              "dataspace for " + where);
  const DatasetHandle set(H5Dcreate2(file_.get(), dataset.c_str(), file_type, space.get(),
                                     link_properties.get(), H5P_DEFAULT, H5P_DEFAULT),
                          "cannot create dataset " + where);
  if (count > 0 && H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) < 0)
    fail("cannot write dataset " + where);
  if (!unit.empty()) {
    const DatatypeHandle text(H5Tcopy(H5T_C_S1), "string type for " + where);
    if (H5Tset_size(text.get(), unit.size()) < 0) fail("string size for " + where);
    const std::string value(unit);
    set_scalar_attribute(set.get(), "unit", text.get(), text.get(), value.c_str());
  }
}

void OutputFile::set_attribute(const std::string& name, double value) {
  set_scalar_attribute(file_.get(), name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void OutputFile::set_attribute(const std::string& name, std::int64_t value) {
  set_scalar_attribute(file_.get(), name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void OutputFile::set_scalar_attribute(hid_t object, const std::string& name, hid_t file_type,
                                      hid_t memory_type, const void* value) {
  const std::string where = "attribute '" + name + "' in '" + path_ + "'";
  const DataspaceHandle scalar(H5Screate(H5S_SCALAR), "scalar dataspace for " + where);
  const AttributeHandle attribute(
      H5Acreate2(object, name.c_str(), file_type, scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
      "cannot create " + where);
  if (H5Awrite(attribute.get(), memory_type, value) < 0) fail("cannot write " + where);
}

void OutputFile::close() {
  file_.close("cannot close '" + path_ + "'");
}

}  // namespace cosim::hdf5
