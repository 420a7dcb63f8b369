// Reading HDF5 files back in tests with the HDF5 C API (tests link HDF5::HDF5 themselves).
#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

namespace tehl::testing {

inline bool Hdf5Exists(hid_t file, const std::string& path) {
  // Checks each prefix, as H5Lexists needs the parents to exist.
  size_t pos = 0;
  while ((pos = path.find('/', pos + 1)) != std::string::npos)
    if (H5Lexists(file, path.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
  return H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0;
}

inline std::vector<double> Hdf5Doubles(hid_t file,
                                       const std::string& path,
                                       std::vector<hsize_t>* dims = nullptr) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> d(rank > 0 ? rank : 0);
  if (rank > 0) H5Sget_simple_extent_dims(space, d.data(), nullptr);
  hsize_t n = 1;
  for (hsize_t x : d) n *= x;
  std::vector<double> v(n);
  if (n > 0) H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(space);
  H5Dclose(set);
  if (dims) *dims = d;
  return v;
}

// A variable-length string attribute of an object ("" when absent).
inline std::string Hdf5StringAttribute(hid_t file,
                                       const std::string& object,
                                       const std::string& name) {
  if (H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return "";
  const hid_t attr = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  const hid_t type = H5Aget_type(attr);
  char* value = nullptr;
  std::string out;
  if (H5Tis_variable_str(type) > 0 && H5Aread(attr, type, &value) >= 0 && value) {
    out = value;
    H5free_memory(value);
  }
  H5Tclose(type);
  H5Aclose(attr);
  return out;
}

// A 1-D dataset of variable-length strings (empty when absent).
inline std::vector<std::string> Hdf5Strings(hid_t file, const std::string& path) {
  std::vector<std::string> out;
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return out;
  const hid_t space = H5Dget_space(set), type = H5Dget_type(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<char*> p(n > 0 ? static_cast<size_t>(n) : 0, nullptr);
  if (!p.empty() && H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()) >= 0) {
    for (char* c : p) out.emplace_back(c ? c : "");
    H5Dvlen_reclaim(type, space, H5P_DEFAULT, p.data());
  }
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(set);
  return out;
}

// A scalar variable-length string dataset.
inline std::string Hdf5Text(hid_t file, const std::string& path) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return "";
  const hid_t type = H5Dget_type(set);
  char* value = nullptr;
  std::string out;
  if (H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) >= 0 && value) {
    out = value;
    H5free_memory(value);
  }
  H5Tclose(type);
  H5Dclose(set);
  return out;
}

}  // namespace tehl::testing
