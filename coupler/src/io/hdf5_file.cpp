#include "hdf5_file.hpp"

#include <algorithm>

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

OutputFile::OutputFile(const std::filesystem::path& path, hid_t access)
    : path_(path.string()),
      file_(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access),
            "cannot create '" + path_ + "'") {}

void OutputFile::write(const std::string& dataset, std::span<const hsize_t> dims,
                       std::span<const double> values, std::string_view unit) {
  write_raw(dataset, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(), values.size(), unit);
}

void OutputFile::write(const std::string& dataset, std::span<const hsize_t> dims, const Part& part,
                       std::span<const double> values, std::string_view unit) {
  if (part.start.size() != dims.size() || part.count.size() != dims.size())
    throw Error(ExitCode::internal_error,
                "HDF5: '" + path_ + ":/" + dataset + "': a part of another rank than its dataset");
  write_raw(dataset, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(), values.size(), unit,
            &part);
}

void OutputFile::write(const std::string& dataset, std::span<const hsize_t> dims,
                       std::span<const std::int64_t> values) {
  write_raw(dataset, dims, H5T_STD_I64LE, H5T_NATIVE_INT64, values.data(), values.size(), {});
}

void OutputFile::write(const std::string& dataset, std::span<const hsize_t> dims, const Rows& rows,
                       std::span<const double> values, std::string_view unit) {
  write_raw(dataset, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(), values.size(), unit,
            nullptr, &rows);
}

void OutputFile::write(const std::string& dataset, std::span<const hsize_t> dims, const Rows& rows,
                       std::span<const std::int64_t> values) {
  write_raw(dataset, dims, H5T_STD_I64LE, H5T_NATIVE_INT64, values.data(), values.size(), {},
            nullptr, &rows);
}

void OutputFile::write_raw(const std::string& dataset, std::span<const hsize_t> dims,
                           hid_t file_type, hid_t memory_type, const void* values,
                           std::size_t count, std::string_view unit, const Part* part,
                           const Rows* rows) {
  const std::string where = "'" + path_ + ":/" + dataset + "'";
  hsize_t expected = 1;
  for (const hsize_t d : part ? part->count : dims) expected *= d;
  if (rows) {
    hsize_t held = 0;
    for (std::size_t k = 1; k < rows->runs.size(); k += 2) held += rows->runs[k];
    expected = dims.empty() || dims[0] == 0 ? 0 : expected / dims[0] * held;
  }
  if (expected != count)
    throw Error(ExitCode::bad_input, "HDF5: " + where + ": " + std::to_string(count) +
                                         " values for a dataspace of " + std::to_string(expected));
  create_groups_above(dataset, where);
  // Without creation times, the same data written twice gives the same
  // bytes (a repeated or restarted run compares its files with cmp).
  const PropertyListHandle dataset_properties(H5Pcreate(H5P_DATASET_CREATE),
                                              "dataset properties for " + where);
  if (H5Pset_obj_track_times(dataset_properties.get(), 0) < 0) fail("untracked times for " + where);
  const DataspaceHandle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                              "dataspace for " + where);
  const DatasetHandle set(H5Dcreate2(file_.get(), dataset.c_str(), file_type, space.get(),
                                     H5P_DEFAULT, dataset_properties.get(), H5P_DEFAULT),
                          "cannot create dataset " + where);
  if (part) {
    const DataspaceHandle mine(
        H5Screate_simple(static_cast<int>(part->count.size()), part->count.data(), nullptr),
        "dataspace of a part of " + where);
    if (H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, part->start.data(), nullptr,
                            part->count.data(), nullptr) < 0)
      fail("a part of " + where);
    if (H5Dwrite(set.get(), memory_type, mine.get(), space.get(), part->transfer, values) < 0)
      fail("cannot write a part of dataset " + where);
  } else if (rows) {
    const hsize_t held[] = {std::max<hsize_t>(count, 1)};
    const DataspaceHandle mine(H5Screate_simple(1, held, nullptr),
                               "dataspace of the rows of " + where);
    if (H5Sselect_none(space.get()) < 0) fail("the rows of " + where);
    if (count == 0 && H5Sselect_none(mine.get()) < 0) fail("no row of " + where);
    std::vector<hsize_t> start(dims.size(), 0), block(dims.begin(), dims.end());
    for (std::size_t k = 0; k + 1 < rows->runs.size(); k += 2) {
      start[0] = rows->runs[k];
      block[0] = rows->runs[k + 1];
      if (H5Sselect_hyperslab(space.get(), H5S_SELECT_OR, start.data(), nullptr, block.data(),
                              nullptr) < 0)
        fail("rows of " + where);
    }
    if (H5Dwrite(set.get(), memory_type, mine.get(), space.get(), rows->transfer, values) < 0)
      fail("cannot write the rows of dataset " + where);
  } else if (count > 0 &&
             H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) < 0) {
    fail("cannot write dataset " + where);
  }
  if (!unit.empty()) {
    const DatatypeHandle text(H5Tcopy(H5T_C_S1), "string type for " + where);
    if (H5Tset_size(text.get(), unit.size()) < 0) fail("string size for " + where);
    const std::string value(unit);
    set_scalar_attribute(set.get(), "unit", text.get(), text.get(), value.c_str());
  }
}

void OutputFile::create_groups_above(const std::string& dataset, const std::string& where) {
  for (std::size_t slash = dataset.find('/', 1); slash != std::string::npos;
       slash = dataset.find('/', slash + 1)) {
    const std::string group = dataset.substr(0, slash);
    const htri_t exists = H5Lexists(file_.get(), group.c_str(), H5P_DEFAULT);
    if (exists < 0) fail("cannot look up group '" + group + "' for " + where);
    if (exists > 0) continue;
    const PropertyListHandle group_properties(H5Pcreate(H5P_GROUP_CREATE),
                                              "group properties for " + where);
    if (H5Pset_obj_track_times(group_properties.get(), 0) < 0)
      fail("untracked times for group '" + group + "'");
    const GroupHandle created(
        H5Gcreate2(file_.get(), group.c_str(), H5P_DEFAULT, group_properties.get(), H5P_DEFAULT),
        "cannot create group '" + group + "' for " + where);
  }
}

void OutputFile::set_attribute(const std::string& name, double value) {
  set_scalar_attribute(file_.get(), name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void OutputFile::set_attribute(const std::string& name, std::int64_t value) {
  set_scalar_attribute(file_.get(), name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void OutputFile::set_attribute(const std::string& name, std::string_view value) {
  const std::string where = "attribute '" + name + "' in '" + path_ + "'";
  const DatatypeHandle text(H5Tcopy(H5T_C_S1), "string type for " + where);
  if (H5Tset_size(text.get(), std::max<std::size_t>(value.size(), 1)) < 0)
    fail("string size for " + where);
  const std::string copy(value);
  set_scalar_attribute(file_.get(), name, text.get(), text.get(), copy.c_str());
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

InputFile::InputFile(const std::filesystem::path& path)
    : path_(path.string()),
      file_(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "cannot open '" + path_ + "'") {}

bool InputFile::has(const std::string& dataset) const {
  const htri_t exists = H5Lexists(file_.get(), dataset.c_str(), H5P_DEFAULT);
  if (exists < 0) fail("cannot look up '" + path_ + ":/" + dataset + "'");
  return exists > 0;
}

std::vector<hsize_t> InputFile::dims(const std::string& dataset) const {
  const std::string where = "'" + path_ + ":/" + dataset + "'";
  const DatasetHandle set(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT),
                          "no dataset " + where);
  const DataspaceHandle space(H5Dget_space(set.get()), "dataspace of " + where);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail("rank of " + where);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0) fail("dims of " + where);
  return dims;
}

namespace {

std::size_t element_count(const std::vector<hsize_t>& dims) {
  std::size_t n = 1;
  for (const hsize_t d : dims) n *= static_cast<std::size_t>(d);
  return n;
}

}  // namespace

std::vector<double> InputFile::read_doubles(const std::string& dataset) const {
  std::vector<double> values(element_count(dims(dataset)));
  read_raw(dataset, H5T_NATIVE_DOUBLE, values.data(), values.size());
  return values;
}

std::vector<std::int64_t> InputFile::read_integers(const std::string& dataset) const {
  std::vector<std::int64_t> values(element_count(dims(dataset)));
  read_raw(dataset, H5T_NATIVE_INT64, values.data(), values.size());
  return values;
}

void InputFile::read_raw(const std::string& dataset, hid_t memory_type, void* values,
                         std::size_t count) const {
  const std::string where = "'" + path_ + ":/" + dataset + "'";
  const DatasetHandle set(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT),
                          "no dataset " + where);
  const DatatypeHandle type(H5Dget_type(set.get()), "type of " + where);
  if (H5Tget_class(type.get()) != H5Tget_class(memory_type))
    throw Error(ExitCode::bad_input, "HDF5: " + where + " holds another type of number");
  if (count > 0 && H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) < 0)
    fail("cannot read " + where);
}

std::string InputFile::string_attribute(const std::string& name) const {
  const std::string where = "attribute '" + name + "' of '" + path_ + "'";
  const AttributeHandle attribute(H5Aopen(file_.get(), name.c_str(), H5P_DEFAULT), "no " + where);
  const DatatypeHandle type(H5Aget_type(attribute.get()), "type of " + where);
  if (H5Tget_class(type.get()) != H5T_STRING)
    throw Error(ExitCode::bad_input, "HDF5: " + where + " is not text");
  std::string value(H5Tget_size(type.get()), '\0');
  if (H5Aread(attribute.get(), type.get(), value.data()) < 0) fail("cannot read " + where);
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

std::int64_t InputFile::integer_attribute(const std::string& name) const {
  const std::string where = "attribute '" + name + "' of '" + path_ + "'";
  const AttributeHandle attribute(H5Aopen(file_.get(), name.c_str(), H5P_DEFAULT), "no " + where);
  const DatatypeHandle type(H5Aget_type(attribute.get()), "type of " + where);
  if (H5Tget_class(type.get()) != H5T_INTEGER)
    throw Error(ExitCode::bad_input, "HDF5: " + where + " is not an integer");
  std::int64_t value = 0;
  if (H5Aread(attribute.get(), H5T_NATIVE_INT64, &value) < 0) fail("cannot read " + where);
  return value;
}

}  // namespace cosim::hdf5
