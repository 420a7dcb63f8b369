// Expansion of a study into scenes and their check as cases (docs/studies.md).
#include "tehl/scene/study.hpp"

#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <set>
#include <system_error>
#include <utility>

#include "io/atomic_file.hpp"
#include "scene/case_plan.hpp"
#include "scene/case_reader.hpp"
#include "scene/film_case.hpp"
#include "scene/gear_case.hpp"
#include "scene/study_case_text.hpp"
#include "scene/study_reader.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using internal::CaseOverride;
using internal::Document;

// Scene value indices: grid = mixed-radix counter, the last [[vary]] fastest; zip = i, i, ...
std::vector<std::vector<int>> Combinations(const std::vector<StudyParameter>& params,
                                           bool zip) {
  std::vector<std::vector<int>> out;
  if (zip) {
    for (size_t i = 0; i < params[0].values_toml.size(); ++i)
      out.emplace_back(params.size(), static_cast<int>(i));
    return out;
  }
  std::vector<int> idx(params.size(), 0);
  while (true) {
    out.push_back(idx);
    int d = static_cast<int>(params.size()) - 1;
    while (d >= 0 && ++idx[d] == static_cast<int>(params[d].values_toml.size())) idx[d--] = 0;
    if (d < 0) break;
  }
  return out;
}

std::string SceneName(int id) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "scene_%04d", id);
  return buf;
}

// Checks a scene's case text with the readers of `tehl run` (schema, cross-key rules, gear
// geometry, film inputs); returns their problems.
// A scene file that cannot be written (a full disk) is that, not problems of the case.
std::vector<InputProblem> CheckScene(const std::string& text, const std::string& tmp_path) {
  {
    errno = 0;  // so that a failure below reports its own cause
    std::ofstream out(tmp_path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out)
      throw fs::filesystem_error(
          "cannot write", tmp_path,
          std::error_code(errno != 0 ? errno : EIO, std::generic_category()));
  }
  Document doc = internal::ReadCaseDocument(tmp_path);
  internal::CheckCasePlan(doc);  // the plan's rules too (steps, grid, memory), as a run
  return doc.problems();
}

// A scene problem reported at the study line of the [[vary]] entry that caused it: the entry
// of that key (its values line), else an entry of the same section (its key line), else the
// first entry.
InputProblem SceneProblem(const std::string& study_path, const Study& s, const StudyScene& sc,
                          const InputProblem& p) {
  std::string key = p.key;
  if (key.size() > 2 && key.front() == '[') key = key.substr(1, key.size() - 2);
  const StudyParameter* hit = nullptr;
  int line = 0;
  size_t which = 0;
  for (size_t i = 0; i < s.parameters.size() && !hit; ++i)
    if (s.parameters[i].key == key) {
      hit = &s.parameters[i];
      line = hit->values_line;
      which = i;
    }
  const std::string section = internal::SplitCaseKey(key).first;
  for (size_t i = 0; i < s.parameters.size() && !hit; ++i) {
    const std::string ps = internal::SplitCaseKey(s.parameters[i].key).first;
    if (ps == key || ps == section) {
      hit = &s.parameters[i];
      line = hit->line;
      which = i;
    }
  }
  if (!hit) {
    hit = &s.parameters[0];
    line = hit->line;
  }
  std::string combo;
  for (size_t i = 0; i < s.parameters.size(); ++i)
    combo += (i ? ", " : "") + s.parameters[i].key + " = " +
             s.parameters[i].values_toml[sc.value_index[i]];
  return {study_path, line, hit->key, hit->values_toml[sc.value_index[which]],
          sc.name + " (" + combo + ") is not a valid case: " + p.key +
              (p.value.empty() ? "" : " = " + p.value) + ": " + p.rule,
          p.allowed};
}

// The folder of the scene files being checked, removed however the check ends.
class ScratchFolder {
 public:
  explicit ScratchFolder(fs::path path) : path_(std::move(path)) { fs::create_directories(path_); }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

std::string Study::ScenesDir() const { return (fs::path(output_dir) / "scenes").string(); }

std::string Study::ResultPath(const StudyScene& scene) const {
  return (fs::path(ScenesDir()) / (scene.name + (gear ? ".h5" : "_steps.csv"))).string();
}

Study ReadStudy(const std::string& study_path, const StudyReadOptions& options) {
  const internal::StudyFile f = internal::ReadStudyFile(study_path);
  Study s;
  s.path = study_path;
  s.base_case_path = f.base_case_path;
  s.name = f.name;
  s.mode = f.mode;
  s.output_dir = options.output_dir.empty() ? f.output : options.output_dir;
  s.parameters = f.parameters;

  // The base case must be valid on its own; its problems name its own file and lines.
  Document base = internal::ReadCaseDocument(s.base_case_path);
  if (base.problems().empty()) {
    if (base.HasSection("gear")) internal::ReadGearCase(base);
    internal::ReadFilmCase(base);
  }
  base.ThrowIfProblems();
  s.gear = base.HasSection("gear") && !base.HasSection("contact");
  const std::string base_text = base.ToToml();
  const std::string scenes_dir = fs::absolute(s.ScenesDir()).lexically_normal().string();

  const ScratchFolder tmp(fs::temp_directory_path() /
                          ("tehl_study_" + std::to_string(getpid()) + "_" +
                           std::to_string(reinterpret_cast<std::uintptr_t>(&s))));
  ProblemList problems;
  std::set<std::string> seen;
  int id = 0;
  for (const auto& combo : Combinations(s.parameters, s.mode == "zip")) {
    StudyScene sc;
    sc.id = id++;
    sc.name = SceneName(sc.id);
    sc.value_index = combo;
    sc.case_path = (fs::path(s.ScenesDir()) / (sc.name + ".toml")).string();
    std::vector<CaseOverride> o;
    std::string header = "# " + sc.name + " of the study " + study_path + "\n# base case: " +
                         s.base_case_path + "\n";
    for (size_t i = 0; i < s.parameters.size(); ++i) {
      o.push_back({s.parameters[i].key, s.parameters[i].values_toml[combo[i]]});
      header += "# varied: " + o.back().key + " = " + o.back().literal + "\n";
    }
    AddPathOverrides(base, s.base_case_path, &o);
    o.push_back({"output.directory", internal::FormatValue(internal::Value(scenes_dir))});
    o.push_back({"output.name", internal::FormatValue(internal::Value(sc.name))});
    sc.case_text = header + internal::ApplyCaseOverrides(base_text, o);
    for (const auto& p : CheckScene(sc.case_text, (tmp.path() / (sc.name + ".toml")).string())) {
      InputProblem q = SceneProblem(study_path, s, sc, p);
      // One report per offending value, not one per scene of the grid that holds it.
      if (seen.insert(std::to_string(q.line) + q.value + p.key + p.rule).second)
        problems.Add(std::move(q));
    }
    s.scenes.push_back(std::move(sc));
  }
  problems.ThrowIfAny();
  return s;
}

void WriteSceneFiles(const Study& study) {
  fs::create_directories(study.ScenesDir());
  for (const auto& sc : study.scenes) internal::WriteTextAtomically(sc.case_path, sc.case_text);
}

}  // namespace tehl
