// Reading a finished scene's result into its row of the study index (study_index.hpp): the
// HDF5 /cycle of a mesh cycle, or the _steps.csv (and _profile.csv) of a contact case.
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/number_text.hpp"
#include "io/hdf5_lock.hpp"
#include "scene/case_reader.hpp"
#include "tehl/ehl/flash_temperature.hpp"
#include "tehl/scene/study_index.hpp"

namespace tehl {
namespace {

// Read-only access to a result file; every call holds the HDF5 lock (io/hdf5_lock.hpp).
class Hdf5Reader {
 public:
  explicit Hdf5Reader(const std::string& path) : lock_(internal::Hdf5LibraryMutex()), path_(path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file_ < 0) throw std::runtime_error("cannot open the result file " + path);
  }
  ~Hdf5Reader() { H5Fclose(file_); }
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  bool Exists(const std::string& name) const {
    size_t pos = 0;
    while ((pos = name.find('/', pos + 1)) != std::string::npos)
      if (H5Lexists(file_, name.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
    return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0;
  }

  std::vector<double> Doubles(const std::string& name) const {
    const hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    if (set < 0) throw std::runtime_error(path_ + ": no dataset " + name);
    const hid_t space = H5Dget_space(set);
    if (space < 0) {
      H5Dclose(set);
      throw std::runtime_error(path_ + ": cannot read " + name);
    }
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    std::vector<double> v(n > 0 ? n : 0);
    const herr_t st =
        v.empty() ? 0 : H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Sclose(space);
    H5Dclose(set);
    if (st < 0) throw std::runtime_error(path_ + ": cannot read " + name);
    return v;
  }

  std::vector<std::string> Strings(const std::string& name) const {
    std::vector<std::string> out;
    const hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    if (set < 0) return out;
    const hid_t space = H5Dget_space(set);
    const hid_t type = H5Dget_type(set);
    const hssize_t n = space < 0 ? 0 : H5Sget_simple_extent_npoints(space);
    std::vector<char*> p(n > 0 && type >= 0 ? n : 0, nullptr);
    if (!p.empty() && H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()) >= 0) {
      for (char* s : p) out.emplace_back(s ? s : "");
      H5Dvlen_reclaim(type, space, H5P_DEFAULT, p.data());
    }
    if (type >= 0) H5Tclose(type);
    if (space >= 0) H5Sclose(space);
    H5Dclose(set);
    return out;
  }

  std::string StringAttribute(const std::string& object, const std::string& name) const {
    if (H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return "";
    const hid_t attr =
        H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (attr < 0) return "";
    const hid_t type = H5Aget_type(attr);
    if (type < 0) {
      H5Aclose(attr);
      return "";
    }
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

  double DoubleAttribute(const std::string& object, const std::string& name) const {
    if (H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0)
      throw std::runtime_error(path_ + ": no attribute " + object + "@" + name);
    const hid_t attr =
        H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (attr < 0) throw std::runtime_error(path_ + ": cannot read " + object + "@" + name);
    double x = 0;
    const herr_t st = H5Aread(attr, H5T_NATIVE_DOUBLE, &x);
    H5Aclose(attr);
    if (st < 0) throw std::runtime_error(path_ + ": cannot read " + object + "@" + name);
    return x;
  }

 private:
  std::lock_guard<std::recursive_mutex> lock_;
  std::string path_;
  hid_t file_ = -1;
};

double Min(const std::vector<double>& v) {
  return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}
double Max(const std::vector<double>& v) {
  return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}
double Mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

// The fewest cells across the Hertzian edge over the films that have one (-1 marks rigid
// solids or no film: hertz_edge.hpp); -1 when none has.
// The largest estimated inlet deficit; -1 (no estimate) stays -1.
double LargestDeficit(const std::vector<double>& deficits) {
  double largest = -1;
  for (double d : deficits) largest = std::max(largest, d);
  return largest;
}

double FewestEdgeCells(const std::vector<double>& cells) {
  double fewest = -1;
  for (double c : cells)
    if (c >= 0 && (fewest < 0 || c < fewest)) fewest = c;
  return fewest;
}

// The rows (grid nodes) of the NAME_profile.csv beside a contact run's NAME_steps.csv; 0 when
// there is none.
double ProfileRows(const std::string& steps_path) {
  const std::string suffix = "_steps.csv";
  if (steps_path.size() < suffix.size() ||
      steps_path.compare(steps_path.size() - suffix.size(), suffix.size(), suffix) != 0)
    return 0;
  std::ifstream in(steps_path.substr(0, steps_path.size() - suffix.size()) + "_profile.csv");
  std::string line;
  double rows = -1;  // the header
  while (std::getline(in, line))
    if (!line.empty()) ++rows;
  return std::max(rows, 0.0);
}

// The values of the usable steps (`usable` empty: every step).
std::vector<double> Kept(const std::vector<double>& v, const std::vector<char>& usable) {
  if (usable.empty()) return v;
  std::vector<double> out;
  for (size_t k = 0; k < v.size() && k < usable.size(); ++k)
    if (usable[k]) out.push_back(v[k]);
  return out;
}

// Blok's flash rises of the usable steps, without those of a Newtonian film whose mu is not
// physical (kPhysicalFrictionLimit); `unphysical` counts those films.
std::vector<double> PhysicalFlash(const std::vector<double>& flash,
                                  const std::vector<double>& mu,
                                  bool newtonian,
                                  double* unphysical) {
  std::vector<double> out;
  for (size_t k = 0; k < flash.size(); ++k) {
    if (newtonian && k < mu.size() && mu[k] > kPhysicalFrictionLimit) {
      *unphysical += 1;
      continue;
    }
    out.push_back(flash[k]);
  }
  return out;
}

SceneRow GearRow(const std::string& path, bool newtonian) {
  const Hdf5Reader h5(path);
  SceneRow r;
  // A run that stopped keeps its failed film as the last row: the summaries are over the
  // converged films only (a steady restart's termination is its steady film's).
  std::vector<char> usable;
  if (h5.Exists("/solver/termination"))
    for (const std::string& t : h5.Strings("/solver/termination"))
      usable.push_back(t == "converged");
  const auto s = Kept(h5.Doubles("/cycle/s"), usable);
  const auto h_min = Kept(h5.Doubles("/cycle/h_min"), usable);
  const auto h_c = Kept(h5.Doubles("/cycle/h_c"), usable);
  r.steps = static_cast<int>(h5.Doubles("/cycle/s").size());
  r.h_min_min_m = Min(h_min);
  r.h_c_min_m = Min(h_c);
  r.p_max_max_pa = Max(Kept(h5.Doubles("/cycle/p_max"), usable));
  // The pitch point: the step nearest s_C (MeshCycleResult::PitchStep()).
  const double s_c = h5.DoubleAttribute("/cycle", "s_C");
  size_t pitch = 0;
  for (size_t i = 1; i < s.size(); ++i)
    if (std::abs(s[i] - s_c) < std::abs(s[pitch] - s_c)) pitch = i;
  r.h_c_pitch_m = h_c.empty() ? 0.0 : h_c[pitch];
  if (h5.Exists("/cycle/T_max")) r.t_max_max_k = Max(Kept(h5.Doubles("/cycle/T_max"), usable));
  std::vector<double> mu;
  if (h5.Exists("/cycle/mu")) {
    mu = Kept(h5.Doubles("/cycle/mu"), usable);
    r.mu_mean = Mean(mu);
    r.mu_max = Max(mu);
  }
  if (h5.Exists("/cycle/T1_max") && h5.Exists("/cycle/T2_max"))
    r.t_surface_max_k = std::max(Max(Kept(h5.Doubles("/cycle/T1_max"), usable)),
                                 Max(Kept(h5.Doubles("/cycle/T2_max"), usable)));
  if (h5.Exists("/cycle/dT_flash_blok"))
    r.flash_blok_max_k = Max(PhysicalFlash(Kept(h5.Doubles("/cycle/dT_flash_blok"), usable), mu,
                                           newtonian, &r.unphysical_mu_films));
  r.wall_time_s = h5.DoubleAttribute("/", "wall_time");
  if (h5.Exists("/solver/steady_restart"))  // files of earlier versions have none
    for (double v : h5.Doubles("/solver/steady_restart")) r.steady_restarts += v;
  if (h5.Exists("/cycle/edge_cells"))
    r.edge_cells_min = FewestEdgeCells(Kept(h5.Doubles("/cycle/edge_cells"), usable));
  if (h5.Exists("/profiles/x"))
    r.grid_points = static_cast<double>(h5.Doubles("/profiles/x").size());
  if (h5.Exists("/cycle/inlet_deficit"))
    r.inlet_deficit_max = LargestDeficit(Kept(h5.Doubles("/cycle/inlet_deficit"), usable));
  const bool ok = h5.StringAttribute("/", "converged") == "true";
  r.status = ok ? "ok" : "not_converged";
  if (!ok) {
    const auto messages = h5.Strings("/solver/message");
    if (!messages.empty()) r.message = messages.back();
  }
  return r;
}

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',')
      out.emplace_back();
    else if (c != '\r')
      out.back() += c;
  }
  return out;
}

// The _steps.csv of a [contact] run. t_max_k, mu and wall_time_s are read when the file has
// them (files of earlier versions do not: those summaries stay 0, as for a gear result without
// /cycle/T_max); the wall time is the sum over the steps.
SceneRow ContactRow(const std::string& path, bool newtonian) {
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error("cannot read " + path);
  const auto head = SplitCsv(line);
  const size_t none = head.size();
  auto find = [&](const std::string& name) {
    return static_cast<size_t>(std::find(head.begin(), head.end(), name) - head.begin());
  };
  auto col = [&](const std::string& name) {
    const size_t i = find(name);
    if (i == none) throw std::runtime_error(path + ": no column " + name);
    return i;
  };
  const size_t ih = col("h_min_m"), ic = col("h_c_m"), ip = col("p_max_pa"),
               it = col("termination");
  const size_t itm = find("t_max_k"), imu = find("mu"), iwt = find("wall_time_s"),
               it1 = find("t1_max_k"), it2 = find("t2_max_k"), ifl = find("dT_flash_blok_k"),
               irs = find("steady_restart"), ied = find("edge_cells"), iin = find("inlet_deficit");
  std::vector<double> h_min, h_c, p_max, t_max, mu, surface, flash, edge, inlet;
  SceneRow r;
  r.status = "ok";
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = SplitCsv(line);
    if (f.size() != head.size()) throw std::runtime_error(path + ": ragged row");
    const auto num = [&](const std::string& cell) {
      return internal::ParseRealOrThrow(cell, path);
    };
    ++r.steps;
    if (iwt != none) r.wall_time_s += num(f[iwt]);
    if (irs != none) r.steady_restarts += num(f[irs]);
    if (f[it] != "converged") {  // a failed film is no result: summaries over the others
      r.status = "not_converged";
      r.message = f[it];
      continue;
    }
    h_min.push_back(num(f[ih]));
    h_c.push_back(num(f[ic]));
    p_max.push_back(num(f[ip]));
    if (itm != none) t_max.push_back(num(f[itm]));
    if (imu != none) mu.push_back(num(f[imu]));
    if (it1 != none && it2 != none) surface.push_back(std::max(num(f[it1]), num(f[it2])));
    if (ifl != none) flash.push_back(num(f[ifl]));
    if (ied != none) edge.push_back(num(f[ied]));
    if (iin != none) inlet.push_back(num(f[iin]));
  }
  r.h_min_min_m = Min(h_min);
  r.h_c_min_m = Min(h_c);
  r.h_c_pitch_m = h_c.empty() ? 0.0 : h_c.back();
  r.p_max_max_pa = Max(p_max);
  r.t_max_max_k = Max(t_max);
  r.mu_mean = Mean(mu);
  r.mu_max = Max(mu);
  r.t_surface_max_k = Max(surface);
  r.flash_blok_max_k = Max(PhysicalFlash(flash, mu, newtonian, &r.unphysical_mu_films));
  r.edge_cells_min = FewestEdgeCells(edge);
  r.inlet_deficit_max = LargestDeficit(inlet);
  r.grid_points = ProfileRows(path);
  return r;
}

}  // namespace

SceneRow ReadSceneRow(const Study& study, const StudyScene& scene) {
  const std::string path = study.ResultPath(scene);
  // Whether the scene's film is Newtonian, for the friction it may report.
  const internal::Document doc = internal::ReadCaseDocument(scene.case_path);
  const bool newtonian = !doc.Bool("effects", "non_newtonian");
  SceneRow r = study.gear ? GearRow(path, newtonian) : ContactRow(path, newtonian);
  // An isothermal contact run writes the inlet temperature as its T_max and surface
  // temperatures; the index has no temperature then, as for an isothermal mesh cycle (0).
  if (!study.gear && doc.problems().empty() && !doc.Bool("effects", "thermal")) {
    r.t_max_max_k = 0;
    r.t_surface_max_k = 0;
  }
  r.scene = scene.id;
  r.result_path = path;
  return r;
}

}  // namespace tehl
