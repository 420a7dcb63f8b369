#include "tehl/io/hdf5_writer.hpp"

#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>

#include "io/hdf5_lock.hpp"

namespace tehl {

namespace internal {
std::recursive_mutex& Hdf5LibraryMutex() {
  static std::recursive_mutex mutex;
  return mutex;
}
}  // namespace internal

namespace {
namespace fs = std::filesystem;

// Held by every public method below (io/hdf5_lock.hpp).
using Hdf5Lock = std::lock_guard<std::recursive_mutex>;

[[noreturn]] void Fail(const std::string& what) {
  throw std::runtime_error("HDF5 result file: " + what);
}

// A file that cannot be created, written, closed or renamed: the folder or the disk, not a
// defect (a full disk, a folder in the way). The command line reports it as such (exit 2).
// (HDF5 does not say why: an input/output error.)
[[noreturn]] void FailIo(const std::string& what, const std::string& path) {
  throw fs::filesystem_error("HDF5 result file: " + what, path,
                             std::make_error_code(std::errc::io_error));
}

// Closes an HDF5 handle of any kind when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

hid_t VariableString() {
  const hid_t t = H5Tcopy(H5T_C_S1);
  if (t < 0) Fail("cannot make a string type");
  if (H5Tset_size(t, H5T_VARIABLE) < 0 || H5Tset_cset(t, H5T_CSET_UTF8) < 0) {
    H5Tclose(t);
    Fail("cannot make a string type");
  }
  return t;
}

void WriteStringAttribute(hid_t object, const std::string& name, const std::string& value) {
  Handle type(VariableString(), H5Tclose);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (H5Aexists(object, name.c_str()) > 0 && H5Adelete(object, name.c_str()) < 0)
    Fail("cannot replace attribute " + name);
  Handle attr(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose);
  const char* p = value.c_str();
  if (!attr.ok() || H5Awrite(attr.get(), type.get(), &p) < 0)
    Fail("cannot write attribute " + name);
}

}  // namespace

void CheckFinite(const std::string& dataset, const std::vector<double>& values) {
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i])) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%g", values[i]);
      throw NonFiniteError("refusing to write a non-finite value: " + dataset + "[" +
                           std::to_string(i) + "] = " + buf);
    }
}

class Hdf5Writer::Impl {
 public:
  std::string final_path;
  hid_t file = -1;
  bool committed = false;

  std::string Temporary() const { return final_path + ".part"; }

  // Creates every missing group on the way to `dataset` ("/a/b/name" creates /a and /a/b).
  void MakeParents(const std::string& dataset) {
    if (dataset.empty() || dataset[0] != '/') Fail("dataset path must be absolute: " + dataset);
    size_t pos = 1;
    while ((pos = dataset.find('/', pos)) != std::string::npos) {
      const std::string group = dataset.substr(0, pos);
      if (H5Lexists(file, group.c_str(), H5P_DEFAULT) <= 0) {
        Handle g(H5Gcreate2(file, group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
        if (!g.ok()) Fail("cannot create group " + group);
      }
      ++pos;
    }
  }

  void Require() const {
    if (file < 0) Fail("the file " + final_path + " is already committed or closed");
  }

  void WriteNumeric(const std::string& dataset,
                    const void* data,
                    hid_t mem_type,
                    hid_t file_type,
                    int rank,
                    const hsize_t* dims,
                    const std::string& unit,
                    const std::string& meaning) {
    Require();
    MakeParents(dataset);
    Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
    Handle set(H5Dcreate2(file, dataset.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                          H5P_DEFAULT),
               H5Dclose);
    if (!set.ok()) Fail("cannot create dataset " + dataset);
    bool empty = false;
    for (int i = 0; i < rank; ++i) empty = empty || dims[i] == 0;
    if (!empty && H5Dwrite(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
      FailIo("cannot write dataset " + dataset, Temporary());
    WriteStringAttribute(set.get(), "unit", unit);
    WriteStringAttribute(set.get(), "meaning", meaning);
  }
};

Hdf5Writer::Hdf5Writer(const std::string& final_path) : impl_(std::make_unique<Impl>()) {
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  impl_->final_path = final_path;
  const fs::path parent = fs::path(final_path).parent_path();
  if (!parent.empty()) fs::create_directories(parent);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr noise
  impl_->file = H5Fcreate(impl_->Temporary().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (impl_->file < 0) FailIo("cannot create " + impl_->Temporary(), impl_->Temporary());
}

Hdf5Writer::~Hdf5Writer() {
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  if (impl_ && !impl_->committed) {
    if (impl_->file >= 0) H5Fclose(impl_->file);
    std::error_code ec;
    fs::remove(impl_->Temporary(), ec);
  }
}

void Hdf5Writer::WriteVector(const std::string& dataset,
                             const std::vector<double>& values,
                             const std::string& unit,
                             const std::string& meaning) {
  CheckFinite(dataset, values);
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  const hsize_t dims[1] = {values.size()};
  impl_->WriteNumeric(dataset, values.data(), H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, 1, dims, unit,
                      meaning);
}

void Hdf5Writer::WriteMatrix(const std::string& dataset,
                             const std::vector<double>& row_major,
                             int rows,
                             int cols,
                             const std::string& unit,
                             const std::string& meaning) {
  if (rows < 0 || cols < 0 || row_major.size() != static_cast<size_t>(rows) * cols)
    Fail(dataset + ": " + std::to_string(row_major.size()) + " values for " + std::to_string(rows) +
         " x " + std::to_string(cols));
  CheckFinite(dataset, row_major);
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  const hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(cols)};
  impl_->WriteNumeric(dataset, row_major.data(), H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, 2, dims, unit,
                      meaning);
}

void Hdf5Writer::WriteInts(const std::string& dataset,
                           const std::vector<int>& values,
                           const std::string& meaning) {
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  const hsize_t dims[1] = {values.size()};
  impl_->WriteNumeric(dataset, values.data(), H5T_NATIVE_INT, H5T_STD_I32LE, 1, dims, "-", meaning);
}

void Hdf5Writer::WriteStrings(const std::string& dataset,
                              const std::vector<std::string>& values,
                              const std::string& meaning) {
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  impl_->Require();
  impl_->MakeParents(dataset);
  std::vector<const char*> ptrs;
  for (const auto& v : values) ptrs.push_back(v.c_str());
  Handle type(VariableString(), H5Tclose);
  const hsize_t dims[1] = {values.size()};
  Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose);
  Handle set(H5Dcreate2(impl_->file, dataset.c_str(), type.get(), space.get(), H5P_DEFAULT,
                        H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose);
  if (!set.ok()) Fail("cannot create dataset " + dataset);
  if (!values.empty() &&
      H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0)
    FailIo("cannot write dataset " + dataset, temporary_path());
  WriteStringAttribute(set.get(), "unit", "");
  WriteStringAttribute(set.get(), "meaning", meaning);
}

void Hdf5Writer::WriteText(const std::string& dataset,
                           const std::string& text,
                           const std::string& meaning) {
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  impl_->Require();
  impl_->MakeParents(dataset);
  Handle type(VariableString(), H5Tclose);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle set(H5Dcreate2(impl_->file, dataset.c_str(), type.get(), space.get(), H5P_DEFAULT,
                        H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose);
  const char* p = text.c_str();
  if (!set.ok() || H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, &p) < 0)
    FailIo("cannot write dataset " + dataset, temporary_path());
  WriteStringAttribute(set.get(), "unit", "");
  WriteStringAttribute(set.get(), "meaning", meaning);
}

void Hdf5Writer::SetAttribute(const std::string& object,
                              const std::string& name,
                              const std::string& value) {
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  impl_->Require();
  Handle obj(H5Oopen(impl_->file, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!obj.ok()) Fail("no object " + object + " for attribute " + name);
  WriteStringAttribute(obj.get(), name, value);
}

static_assert(sizeof(hid_t) <= sizeof(long long), "hid_t is passed as long long");

void Hdf5Writer::SetScalarAttribute(const std::string& object,
                                    const std::string& name,
                                    long long file_type,
                                    long long memory_type,
                                    const void* value,
                                    const std::string& unit) {
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  impl_->Require();
  Handle obj(H5Oopen(impl_->file, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!obj.ok()) Fail("no object " + object + " for attribute " + name);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (H5Aexists(obj.get(), name.c_str()) > 0) H5Adelete(obj.get(), name.c_str());
  Handle attr(H5Acreate2(obj.get(), name.c_str(), static_cast<hid_t>(file_type), space.get(),
                         H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose);
  if (!attr.ok() || H5Awrite(attr.get(), static_cast<hid_t>(memory_type), value) < 0)
    Fail("cannot write attribute " + name);
  WriteStringAttribute(obj.get(), name + "_unit", unit);
}

void Hdf5Writer::SetAttribute(const std::string& object,
                              const std::string& name,
                              double value,
                              const std::string& unit) {
  CheckFinite(object + "@" + name, {value});
  SetScalarAttribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value, unit);
}

void Hdf5Writer::SetIntAttribute(const std::string& object,
                                 const std::string& name,
                                 long long value) {
  SetScalarAttribute(object, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, &value, "-");
}

void Hdf5Writer::Commit() {
  Hdf5Lock lock(internal::Hdf5LibraryMutex());
  impl_->Require();
  const bool flushed = H5Fflush(impl_->file, H5F_SCOPE_GLOBAL) >= 0;
  const bool closed = H5Fclose(impl_->file) >= 0;
  impl_->file = -1;
  if (!flushed || !closed) FailIo("cannot close " + temporary_path(), temporary_path());
  std::error_code ec;
  fs::rename(temporary_path(), impl_->final_path, ec);
  if (ec)
    throw fs::filesystem_error("HDF5 result file: cannot rename " + temporary_path(),
                               temporary_path(), impl_->final_path, ec);
  impl_->committed = true;
}

const std::string& Hdf5Writer::final_path() const { return impl_->final_path; }
std::string Hdf5Writer::temporary_path() const { return impl_->Temporary(); }

}  // namespace tehl
