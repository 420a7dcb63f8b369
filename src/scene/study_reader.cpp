// Reading a study file: the [study] table through the declarative schema (Document), the
// [[vary]] array of tables checked entry by entry (study_vary_reader.cpp: the schema describes
// tables, not arrays of them), then the entries together (keys and labels unique, the scene
// count), every problem with file:line, key, value, rule and what is allowed.
#include "scene/study_reader.hpp"

#include <filesystem>
#include <set>
#include <toml.hpp>

#include "scene/study_vary_reader.hpp"
#include "tehl/scene/study_index.hpp"

namespace tehl::internal {
namespace {
namespace fs = std::filesystem;

const Schema& StudySchema() {
  static const Schema schema = [] {
    Schema s;
    s.kind = "study";
    s.sections = {
        {"", "top level: only [study] and [[vary]] entries", false, {}},
        {"study", "the base case and how the [[vary]] entries combine", true, {
          Required(Text("base", "", "the base case file, relative to the study file"),
                   "\"../seed004_sae40.toml\""),
          Text("mode", "\"grid\"", "grid: every combination; zip: the lists in parallel",
               {"grid", "zip"}),
          Text("name", "\"\"", "name of the study; empty = the study file's name"),
          Text("output", "\"\"", "folder of the study's results (relative to the working "
               "directory, as [output] directory of a case); empty = results/<name>"),
        }},
    };
    return s;
  }();
  return schema;
}

}  // namespace

StudyFile ReadStudyFile(const std::string& path) {
  StudyFile f;
  const Document doc = Document::ReadFile(StudySchema(), path);
  ProblemList problems;
  bool syntax = false;
  for (const auto& p : doc.problems()) {
    if (p.key == "vary" && p.rule == "unknown key") continue;  // the [[vary]] array: below
    syntax = syntax || p.key == "(syntax)" || p.key == "(file)";
    problems.Add(p);
  }
  if (!syntax) {
    toml::value root;
    try {
      root = toml::parse(path);
    } catch (const std::exception&) {
      syntax = true;  // already reported by the Document
    }
    if (!syntax && root.is_table()) {
      const auto& top = root.as_table();
      const auto v = top.find("vary");
      const int study_line = doc.Line("study", "");
      if (v == top.end()) {
        problems.Add({path, study_line, "[[vary]]", "", "the study varies nothing",
                      "at least one [[vary]] entry with key and values"});
      } else if (!v->second.is_array() || v->second.as_array().empty() ||
                 !v->second.as_array()[0].is_table()) {
        problems.Add({path, TomlLine(v->second), "vary", ShowStudyValue(v->second),
                      "must be an array of tables", "[[vary]] entries with key and values"});
      } else {
        int n = 0;
        std::set<std::string> seen, labels;
        for (const auto& t : v->second.as_array()) {
          ++n;
          if (!t.is_table()) continue;
          if (auto p = ReadVaryTable(path, t, n, TomlLine(t), &problems)) {
            if (!seen.insert(p->key).second) {
              problems.Add({path, p->line, "vary[" + std::to_string(n) + "].key",
                            FormatValue(Value(p->key)), "the key is varied twice",
                            "each case key in one [[vary]] entry"});
              continue;
            }
            // Labels name the index's columns and datasets (/parameters/LABEL): unique, and
            // none of the index's own columns.
            if (IsIndexColumnName(p->label) || !labels.insert(p->label).second) {
              problems.Add({path, p->line, "vary[" + std::to_string(n) + "].label",
                            FormatValue(Value(p->label)),
                            IsIndexColumnName(p->label)
                                ? "is the name of a column the index writes itself"
                                : "is the label of another [[vary]] entry",
                            "a label (or key) of its own, not scene, steps, status, computed, "
                            "result or a summary column"});
              continue;
            }
            f.parameters.push_back(std::move(*p));
          }
        }
      }
    }
  }
  f.mode = doc.String("study", "mode");
  f.name = doc.String("study", "name");
  // The name makes the default output folder results/<name>: one folder name, not a path.
  if (!f.name.empty() &&
      (f.name.find_first_of("/\\") != std::string::npos || f.name == "." || f.name == ".."))
    problems.Add({path, doc.Line("study", "name"), "study.name", FormatValue(Value(f.name)),
                  "names the study's folder under results/: a path would put it elsewhere",
                  "a name without / (output = \"DIR\" chooses the folder)"});
  if (f.name.empty()) f.name = fs::path(path).stem().string();
  f.output = doc.String("study", "output");
  if (f.output.empty()) f.output = (fs::path("results") / f.name).string();
  f.base_line = doc.Line("study", "base");
  f.mode_line = doc.Line("study", "mode");
  const std::string base = doc.String("study", "base");
  if (!base.empty()) {
    fs::path b(base);
    if (b.is_relative()) b = fs::path(path).parent_path() / b;
    f.base_case_path = b.lexically_normal().string();
    std::error_code ec;
    if (!fs::is_regular_file(f.base_case_path, ec))
      problems.Add({path, f.base_line, "study.base", FormatValue(Value(base)),
                    "no such case file (looked for " + f.base_case_path + ")",
                    "a case file path relative to the study file"});
  }
  // Scene count: zip needs equal lengths; grid multiplies.
  if (problems.empty() && !f.parameters.empty()) {
    const size_t n0 = f.parameters[0].values_toml.size();
    double total = 1;
    for (size_t i = 0; i < f.parameters.size(); ++i) {
      const auto& p = f.parameters[i];
      total *= static_cast<double>(p.values_toml.size());
      if (f.mode == "zip" && p.values_toml.size() != n0)
        problems.Add({path, p.values_line, "vary[" + std::to_string(i + 1) + "].values",
                      std::to_string(p.values_toml.size()) + " values",
                      "mode = \"zip\" needs lists of equal length: the first [[vary]] has " +
                          std::to_string(n0),
                      std::to_string(n0) + " values, or mode = \"grid\""});
    }
    if (f.mode == "grid" && total > kMaxStudyScenes)
      problems.Add({path, f.mode_line, "study.mode", "\"grid\"",
                    "the grid has " + FormatReal(total) + " scenes",
                    "at most " + std::to_string(kMaxStudyScenes) + " scenes"});
  }
  problems.ThrowIfAny();
  return f;
}

}  // namespace tehl::internal
