#pragma once

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>

// Thin RAII layer over the HDF5 C API for the snapshot writer: every handle
// closes itself, every failure becomes cosim::Error with HDF5's own message.
namespace cosim::hdf5 {

// Switches off HDF5's printing of its error stack to stderr for the calling
// thread; failures are reported through exceptions instead.
void silence_error_printing();

// Throws Error "HDF5: <what>: <messages of the HDF5 error stack>" and clears the stack.
[[noreturn]] void fail(const std::string& what);

template <herr_t (*Close)(hid_t)>
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, const std::string& what) : id_(id) {
    if (id_ < 0) fail(what);
  }
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  // Closes now and reports a failure (a file's close flushes its data).
  void close(const std::string& what) {
    const hid_t id = std::exchange(id_, H5I_INVALID_HID);
    if (id >= 0 && Close(id) < 0) fail(what);
  }

 private:
  void reset() {
    if (id_ >= 0) Close(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
};

using FileHandle = Handle<H5Fclose>;
using DatasetHandle = Handle<H5Dclose>;
using DataspaceHandle = Handle<H5Sclose>;
using DatatypeHandle = Handle<H5Tclose>;
using AttributeHandle = Handle<H5Aclose>;
using PropertyListHandle = Handle<H5Pclose>;

// A new HDF5 file (an existing one is truncated) to which datasets and
// attributes are added by path; intermediate groups are created as needed.
class OutputFile {
 public:
  explicit OutputFile(const std::filesystem::path& path);

  void write(const std::string& dataset, std::span<const hsize_t> dims,
             std::span<const double> values, std::string_view unit = {});
  void write(const std::string& dataset, std::span<const hsize_t> dims,
             std::span<const std::int64_t> values);
  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, std::int64_t value);
  // Closes and flushes the file; throws if that fails.
  void close();

 private:
  void write_raw(const std::string& dataset, std::span<const hsize_t> dims, hid_t file_type,
                 hid_t memory_type, const void* values, std::size_t count, std::string_view unit);
  void set_scalar_attribute(hid_t object, const std::string& name, hid_t file_type,
                            hid_t memory_type, const void* value);

  std::string path_;
  FileHandle file_;
};

}  // namespace cosim::hdf5
