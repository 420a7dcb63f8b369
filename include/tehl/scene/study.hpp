// A study: one base case expanded into many scenes by varying case keys (docs/studies.md;
// DESIGN.md section 6, "Sweeps"). The study file names the base case and, per [[vary]]
// entry, a case key by its dotted path and its values (a list, or a linear or logarithmic
// range). mode = "grid" takes the full Cartesian product of the value lists, mode = "zip"
// takes them in parallel (lists of equal length).
//
// Each scene is the base case as run (defaults filled) with the overrides applied, written as
// a complete case file <output>/scenes/scene_NNNN.toml and checked by the same readers as
// `tehl run` before anything runs. A scene that is not a valid case is reported at the line
// of the [[vary]] entry that made it so (InputError, file:line).
#pragma once

#include <string>
#include <vector>

namespace tehl {

// One [[vary]] entry.
struct StudyParameter {
  std::string key;       // dotted case key, e.g. "surfaces.surface1.amplitude_m"
  std::string label;     // column name in the index; default: the key
  std::string unit;      // the case key's unit ("" for text, "-" dimensionless)
  bool numeric = true;   // every value is a number (index column of doubles)
  int line = 0;          // line of `key =` in the study file (1-based)
  int values_line = 0;   // line of `values =` or `from =`
  std::vector<std::string> values_toml;  // each value as a TOML literal ("1e-07", "\"sae90\"")
  std::vector<double> values_number;     // the values as numbers (numeric parameters only)
};

struct StudyScene {
  int id = 0;                        // 0-based scene number [-]
  std::string name;                  // "scene_0007"
  std::vector<int> value_index;      // index into each parameter's values
  std::string case_text;             // the complete case file of the scene (TOML)
  std::string case_path;             // <output>/scenes/<name>.toml
};

struct Study {
  std::string path;              // the study file
  std::string base_case_path;    // the base case, resolved relative to the study file
  std::string name;              // [study] name; default: the study file's stem
  std::string mode;              // "grid" or "zip"
  std::string output_dir;        // the study's folder (index files); scenes in <output>/scenes
  bool gear = true;              // the base is a [gear] case (else a [contact] case)
  std::vector<StudyParameter> parameters;
  std::vector<StudyScene> scenes;

  std::string ScenesDir() const;   // <output_dir>/scenes
  // The file whose final name marks a finished scene: <scenes>/<name>.h5 for gear cases
  // (written atomically by the mesh cycle), <scenes>/<name>_steps.csv for contact cases.
  std::string ResultPath(const StudyScene& scene) const;
};

struct StudyReadOptions {
  std::string output_dir;   // overrides [study] output when not empty
};

// Reads the study file and expands it into its scenes; every scene is checked as a case
// (schema, cross-key rules, gear geometry, film inputs). Writes nothing. Throws InputError
// with every problem (file:line of the study file, or of the base case for problems of the
// base itself).
Study ReadStudy(const std::string& study_path, const StudyReadOptions& options = {});

// Writes each scene's case file into Study::ScenesDir() (atomically; creates the folders).
void WriteSceneFiles(const Study& study);

}  // namespace tehl
