// Shared by the sweep tests: a reduced-resolution seed 004 base case (129 nodes, 40 steps),
// a study file around it, and the index read back (HDF5 C API).
#pragma once

#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "regression/mesh_cycle_runs.hpp"
#include "unit/io/hdf5_read.hpp"

namespace tehl::testing {

// A folder with a study file `study.toml` varying `vary_body` ([[vary]] entries) over the
// seed 004 SAE 40 case at 129 nodes and 40 steps. Returns the study path.
inline std::string ReducedStudy(const std::string& name, const std::string& vary_body) {
  const std::string base = ReducedCase("seed004_sae40", Reduced({{"grid_points", "129"}}));
  const std::string dir = TempDirFor(name);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/study.toml";
  std::ofstream(path) << "[study]\nbase = \"" << base << "\"\n" << vary_body;
  return path;
}

struct IndexTable {
  std::vector<double> scene, h_min_min, h_c_pitch, h_c_min, p_max_max, t_max_max, mu_mean,
      mu_max, computed;
  std::vector<std::string> status, result;
};

inline std::vector<double> Hdf5IntsAsDoubles(hid_t file, const std::string& path) {
  return Hdf5Doubles(file, path);  // H5Dread converts the stored int32 to double
}

inline IndexTable ReadIndex(const std::string& index_h5) {
  IndexTable t;
  const hid_t f = H5Fopen(index_h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << index_h5;
  if (f < 0) return t;
  t.scene = Hdf5IntsAsDoubles(f, "/scene");
  t.computed = Hdf5IntsAsDoubles(f, "/computed");
  t.h_min_min = Hdf5Doubles(f, "/summary/h_min_min");
  t.h_c_pitch = Hdf5Doubles(f, "/summary/h_c_pitch");
  t.h_c_min = Hdf5Doubles(f, "/summary/h_c_min");
  t.p_max_max = Hdf5Doubles(f, "/summary/p_max_max");
  t.t_max_max = Hdf5Doubles(f, "/summary/T_max_max");
  t.mu_mean = Hdf5Doubles(f, "/summary/mu_mean");
  t.mu_max = Hdf5Doubles(f, "/summary/mu_max");
  t.status = Hdf5Strings(f, "/status");
  t.result = Hdf5Strings(f, "/result");
  H5Fclose(f);
  return t;
}

// |a - b| <= rel |b| for every element, with a message naming the column and row.
inline void ExpectClose(const std::vector<double>& a, const std::vector<double>& b, double rel,
                        const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i)
    EXPECT_NEAR(a[i], b[i], rel * std::abs(b[i])) << what << "[" << i << "]";
}

}  // namespace tehl::testing
