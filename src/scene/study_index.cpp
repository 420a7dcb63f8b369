#include "tehl/scene/study_index.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "base/number_text.hpp"
#include "io/atomic_file.hpp"
#include "tehl/io/hdf5_writer.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

// The numeric summary of a row, in the order of the CSV columns and of the text form.
struct SummaryColumn {
  const char* csv;   // CSV column
  const char* hdf5;  // dataset under /summary
  const char* unit;
  const char* meaning;
  double SceneRow::*field;
};

const std::vector<SummaryColumn>& SummaryColumns() {
  static const std::vector<SummaryColumn> cols = {
      {"h_min_min_m", "h_min_min", "m", "minimum over the cycle of the minimum film thickness",
       &SceneRow::h_min_min_m},
      {"h_c_pitch_m", "h_c_pitch", "m", "central film thickness at the pitch point",
       &SceneRow::h_c_pitch_m},
      {"h_c_min_m", "h_c_min", "m", "minimum over the cycle of the central film thickness",
       &SceneRow::h_c_min_m},
      {"p_max_max_pa", "p_max_max", "Pa", "maximum over the cycle of the film pressure",
       &SceneRow::p_max_max_pa},
      {"t_max_max_k", "T_max_max", "K",
       "maximum over the cycle of the film temperature (0: not in the result)",
       &SceneRow::t_max_max_k},
      {"mu_mean", "mu_mean", "-", "mean friction coefficient over the steps (0: not in the result)",
       &SceneRow::mu_mean},
      {"mu_max", "mu_max", "-",
       "maximum friction coefficient over the steps (0: not in the result)", &SceneRow::mu_max},
      {"wall_time_s", "wall_time", "s", "run time of the scene", &SceneRow::wall_time_s},
      {"t_surface_max_k", "T_surface_max", "K",
       "maximum over the cycle of the hottest surface temperature of either body (0: not in the "
       "result)",
       &SceneRow::t_surface_max_k},
      {"dT_flash_blok_max_k", "dT_flash_blok_max", "K",
       "maximum over the cycle of Blok's flash temperature rise with the film's mu (0: not in "
       "the result)",
       &SceneRow::flash_blok_max_k},
      {"steady_restarts", "steady_restarts", "-",
       "time steps that did not converge and were replaced by the steady film at their time "
       "([numerics] failed_step; 0 in results of earlier versions)",
       &SceneRow::steady_restarts},
      {"edge_cells_min", "edge_cells_min", "-",
       "fewest grid cells across a film's Hertzian edge; below 10 that film is likely more "
       "than 1 % too thin (-1: rigid solids, or results of earlier versions)",
       &SceneRow::edge_cells_min},
      {"grid_points", "grid_points", "-",
       "nodes of the film grid: the case's [numerics] grid_points, or the automatic grid's "
       "(0: not in the result)",
       &SceneRow::grid_points},
      {"inlet_deficit_max", "inlet_deficit_max", "-",
       "largest estimated film deficit of the truncated inlet over the films; above 0.005 the "
       "inlet thins them (-1: no estimate, or results of earlier versions)",
       &SceneRow::inlet_deficit_max},
      {"unphysical_mu_films", "unphysical_mu_films", "-",
       "converged Newtonian films whose friction coefficient exceeds 0.2, which a full film "
       "cannot carry; their flash temperatures are left out of dT_flash_blok_max_k "
       "([effects] non_newtonian = true bounds the friction)",
       &SceneRow::unphysical_mu_films},
  };
  return cols;
}

std::string OneLine(std::string s) {
  for (char& c : s)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return s;
}

std::string CsvText(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// A varied value in the CSV: a TOML string literal without escapes as its plain text (the CSV
// quotes it itself where needed), anything else (numbers, booleans, arrays) as written.
std::string PlainValue(const std::string& literal) {
  const size_t n = literal.size();
  if (n >= 2 && (literal[0] == '"' || literal[0] == '\'') && literal[n - 1] == literal[0] &&
      literal.find('\\') == std::string::npos && literal.find(literal[0], 1) == n - 1)
    return literal.substr(1, n - 2);
  return literal;
}

// Paths in the index are absolute, so that a script opening it from any folder finds the
// files ("" stays "": a scene that failed has no result).
std::string Absolute(const std::string& path) {
  if (path.empty()) return path;
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

std::string Num(double x) {
  char buf[40];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);  // round trip
}

// The HDF5 dataset name of a parameter label ('/' separates groups).
std::string DatasetName(std::string label) {
  std::replace(label.begin(), label.end(), '/', '_');
  return label;
}

}  // namespace

bool IsIndexColumnName(const std::string& name) {
  for (const char* own : {"scene", "steps", "status", "computed", "result", "message"})
    if (name == own) return true;
  for (const SummaryColumn& c : SummaryColumns())
    if (name == c.csv || name == c.hdf5) return true;
  return false;
}

SceneRow FailedSceneRow(const StudyScene& scene, const std::string& what) {
  SceneRow r;
  r.scene = scene.id;
  r.status = "failed: " + OneLine(what);
  r.message = OneLine(what);
  return r;
}

std::string SceneRowsToText(const std::vector<SceneRow>& rows) {
  std::ostringstream o;
  for (const auto& r : rows) {
    o << r.scene << '\t' << OneLine(r.status) << '\t' << OneLine(r.message) << '\t'
      << OneLine(r.result_path) << '\t' << (r.computed ? 1 : 0) << '\t' << r.steps;
    for (const SummaryColumn& c : SummaryColumns()) o << '\t' << Num(r.*c.field);
    o << '\n';
  }
  return o.str();
}

std::vector<SceneRow> SceneRowsFromText(const std::string& text) {
  std::vector<SceneRow> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    std::vector<std::string> f(1);
    for (char c : line) {
      if (c == '\t') f.emplace_back();
      else f.back() += c;
    }
    const size_t numeric = SummaryColumns().size();
    if (f.size() != 6 + numeric) throw std::runtime_error("malformed scene row: " + line);
    SceneRow r;
    r.scene = std::stoi(f[0]);
    r.status = f[1];
    r.message = f[2];
    r.result_path = f[3];
    r.computed = f[4] == "1";
    r.steps = std::stoi(f[5]);
    for (size_t i = 0; i < numeric; ++i)
      r.*SummaryColumns()[i].field =
          internal::ParseRealOrThrow(f[6 + i], "scene row " + f[0], /*allow_non_finite=*/true);
    rows.push_back(std::move(r));
  }
  return rows;
}

std::vector<std::string> WriteStudyIndex(const Study& study, std::vector<SceneRow> rows) {
  std::sort(rows.begin(), rows.end(),
            [](const SceneRow& a, const SceneRow& b) { return a.scene < b.scene; });
  fs::create_directories(study.output_dir);
  const std::string h5_path = (fs::path(study.output_dir) / "index.h5").string();
  const std::string csv_path = (fs::path(study.output_dir) / "index.csv").string();
  auto column = [&](double SceneRow::*field) {
    std::vector<double> v;
    for (const auto& r : rows) v.push_back(r.*field);
    return v;
  };
  std::vector<int> ids, computed, steps;
  std::vector<std::string> status, message, result;
  for (const auto& r : rows) {
    ids.push_back(r.scene);
    computed.push_back(r.computed ? 1 : 0);
    steps.push_back(r.steps);
    status.push_back(r.status);
    message.push_back(r.message);
    result.push_back(Absolute(r.result_path));
  }
  {
    Hdf5Writer h5(h5_path);
    h5.SetAttribute("/", "program", "tehl 0.1.0");
    h5.SetAttribute("/", "study_file", Absolute(study.path));
    h5.SetAttribute("/", "base_case", Absolute(study.base_case_path));
    h5.SetAttribute("/", "mode", study.mode);
    h5.SetAttribute("/", "name", study.name);
    h5.SetAttribute("/", "kind", study.gear ? "mesh_cycle" : "contact");
    h5.WriteInts("/scene", ids, "scene id (scenes/scene_NNNN)");
    h5.WriteStrings("/status", status, "ok, not_converged, or failed: <message>");
    h5.WriteStrings("/message", message, "solver message of the last step when not ok");
    h5.WriteStrings("/result", result, "the scene's result file");
    h5.WriteInts("/computed", computed, "1: run by this sweep, 0: read back (--resume)");
    h5.WriteInts("/steps", steps, "rows of the scene's cycle table");
    std::vector<std::string> labels;
    for (const auto& p : study.parameters) {
      const std::string name = "/parameters/" + DatasetName(p.label);
      labels.push_back(p.label);
      if (p.numeric) {
        std::vector<double> v;
        for (const auto& r : rows)
          v.push_back(p.values_number[study.scenes[r.scene].value_index[&p - &study.parameters[0]]]);
        h5.WriteVector(name, v, p.unit.empty() ? "-" : p.unit, "varied case key " + p.key);
      } else {
        std::vector<std::string> v;
        for (const auto& r : rows)
          v.push_back(p.values_toml[study.scenes[r.scene].value_index[&p - &study.parameters[0]]]);
        h5.WriteStrings(name, v, "varied case key " + p.key + " (TOML literals)");
      }
      h5.SetAttribute(name, "key", p.key);
    }
    h5.WriteStrings("/parameter_labels", labels, "the [[vary]] labels, in study order");
    for (const SummaryColumn& c : SummaryColumns())
      h5.WriteVector(std::string("/summary/") + c.hdf5, column(c.field), c.unit, c.meaning);
    h5.Commit();
  }
  std::ostringstream csv;
  csv << "scene";
  for (const auto& p : study.parameters) csv << ',' << CsvText(p.label);
  for (const SummaryColumn& c : SummaryColumns()) csv << ',' << c.csv;
  csv << ",steps,status,computed,result\n";
  for (const auto& r : rows) {
    csv << r.scene;
    for (size_t i = 0; i < study.parameters.size(); ++i)
      csv << ','
          << CsvText(
                 PlainValue(study.parameters[i].values_toml[study.scenes[r.scene].value_index[i]]));
    for (const SummaryColumn& c : SummaryColumns()) csv << ',' << Num(r.*c.field);
    csv << ',' << r.steps << ',' << CsvText(r.status) << ',' << (r.computed ? 1 : 0) << ','
        << CsvText(Absolute(r.result_path)) << '\n';
  }
  internal::WriteTextAtomically(csv_path, csv.str());
  return {h5_path, csv_path};
}

}  // namespace tehl
