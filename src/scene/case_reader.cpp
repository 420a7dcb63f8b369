#include "scene/case_reader.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "io/data_dir.hpp"
#include "tehl/scene/case_schema.hpp"

namespace tehl::internal {
namespace fs = std::filesystem;

std::string ResolveLubricantPath(const std::string& name, const std::string& case_path) {
  if (name.empty()) return "";
  std::vector<fs::path> candidates;
  const fs::path as_given(name);
  // A case given by its bare file name lies in the working folder.
  fs::path case_dir = fs::path(case_path).parent_path();
  if (case_dir.empty() && !case_path.empty()) case_dir = ".";
  const std::string file = as_given.has_extension() ? name : name + ".toml";
  candidates.push_back(as_given);
  if (!case_dir.empty()) {
    candidates.push_back(case_dir / as_given);
    candidates.push_back(case_dir / file);
  }
  if (const char* env = std::getenv("TEHL_LUBRICANT_DIR")) candidates.push_back(fs::path(env) / file);
  if (!case_dir.empty()) candidates.push_back(case_dir / ".." / "lubricants" / file);
  for (const fs::path& d : DataDirs("lubricants", nullptr)) candidates.push_back(d / file);
  for (const auto& c : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(c, ec)) return c.lexically_normal().string();
  }
  return "";
}

std::string LubricantSearchText(const std::string& case_path) {
  // In the order searched (ResolveLubricantPath).
  std::string s = "sae40, sae90, reference_z068 or NAME, as NAME.toml";
  if (!case_path.empty()) s += " beside the case,";
  s += " in $TEHL_LUBRICANT_DIR";
  if (!case_path.empty()) s += ", in ../lubricants of the case";
  for (const fs::path& d : DataDirs("lubricants", nullptr)) s += ", in " + d.string();
  return s + "; or a path to a lubricant .toml file";
}

Document ReadCaseDocument(const std::string& path) {
  Document doc = Document::ReadFile(CaseSchema(), path);
  // An unreadable file (a problem of the file itself or of its TOML syntax): the cross-key rules
  // would only repeat it.
  for (const InputProblem& p : doc.problems())
    if (p.key == "(file)" || p.key == "(syntax)") return doc;

  const bool gear = doc.HasSection("gear") || doc.HasSection("gear.pinion") ||
                    doc.HasSection("gear.wheel");
  const bool contact = doc.HasSection("contact");
  if (gear == contact) {
    doc.Problem(gear ? "contact" : "gear", "", gear ? "a case has either [gear] or [contact], "
                "not both" : "a case needs a [gear] pair or a [contact]",
                "[gear] with [gear.pinion], [gear.wheel] and [operating]; or [contact]");
  }
  if (gear) {
    for (const char* member : {"gear.pinion", "gear.wheel"})
      if (!doc.HasSection(member))
        doc.Problem(member, "", "required section is missing for a gear case",
                    std::string("a [") + member + "] table with at least teeth");
    // A key written with a wrong value (reported above) counts as given: it is not missing.
    auto written = [&](const char* key) {
      if (doc.Given("operating", key)) return 1;
      const std::string full = std::string("operating.") + key;
      for (const InputProblem& p : doc.problems())
        if (p.key == full) return 1;
      return 0;
    };
    const int speeds = written("pinion_speed_rpm") + written("pinion_speed_rad_s");
    const int loads = written("power_w") + written("pinion_torque_nm");
    if (doc.HasSection("motor")) {  // the motor gives the speed, the load the torque
      if (speeds > 0)
        doc.Problem("operating", doc.Given("operating", "pinion_speed_rpm") ? "pinion_speed_rpm"
                                                                          : "pinion_speed_rad_s",
                    "[motor] gives the pinion speed: speed given twice",
                    "no pinion speed in [operating] with a [motor]");
      if (doc.Given("operating", "power_w"))
        doc.Problem("operating", "power_w", "with a [motor] the load is a torque",
                    "pinion_torque_nm");
    } else if (speeds != 1) {
      doc.Problem("operating", "pinion_speed_rpm",
                  speeds ? "give the speed once, not twice" : "the pinion speed is missing",
                  "exactly one of pinion_speed_rpm, pinion_speed_rad_s");
    }
    if (loads != 1)
      doc.Problem("operating", "power_w",
                  loads ? "give the load once, not twice" : "the transmitted load is missing",
                  "exactly one of power_w, pinion_torque_nm");
    // A length in millimetres where metres are due passes every range: it shows as a face
    // width of a sliver of a module, or of thousands of modules. Spur gears have b/m from
    // about 3 (FZG type C: 14 mm / 4.5 mm) to about 40 (wide industrial gears).
    // A module in millimetres with the face width in millimetres too keeps b/m plausible;
    // the module alone then gives it away (the largest spur gears have m of about 50 mm).
    if (doc.Given("gear", "module_m") && doc.Real("gear", "module_m") > kMaxModuleM)
      doc.Problem(
          "gear", "module_m",
          "a module of " + FormatShort(doc.Real("gear", "module_m")) + " m: in millimetres?",
          "module_m in metres (3 mm = 0.003), at most " + FormatShort(kMaxModuleM) +
              " m (lengths such as face_width_m in metres too)");
    else if (doc.Given("gear", "module_m") && doc.Given("gear", "face_width_m")) {
      const double b_m = doc.Real("gear", "face_width_m") / doc.Real("gear", "module_m");
      if (b_m < 0.2)
        doc.Problem("gear", "module_m",
                    "the face width is " + FormatShort(b_m) + " modules: a module in millimetres?",
                    "module_m in metres (2 mm = 0.002), at most 5 face widths");
      else if (b_m > 200.0)
        doc.Problem(
            "gear", "face_width_m",
            "the face width is " + FormatShort(b_m) + " modules: a face width in millimetres?",
            "face_width_m in metres (25 mm = 0.025), at most 200 modules");
    }
  } else if (doc.HasSection("motor")) {
    doc.Problem("motor", "", "[motor] drives the pinion of a gear pair",
                "a [gear] case, or no [motor]");
  }
  // The result files are written into the output folder under this name: a plain file name,
  // so that they stay in that folder (no folder part, no "..") and fit any file system.
  if (doc.Given("output", "name")) {
    const std::string name = doc.String("output", "name");
    const bool plain = name.size() <= kMaxOutputNameChars && name != "." && name != ".." &&
                       std::none_of(name.begin(), name.end(), [](char ch) {
                         return ch == '/' || ch == '\\' || static_cast<unsigned char>(ch) < 0x20;
                       });
    if (!plain)
      doc.Problem("output", "name",
                  "the result files' base name must be a plain file name inside the output "
                  "folder",
                  "a name of at most " + std::to_string(kMaxOutputNameChars) +
                      " characters without '/', '\\', control characters, or \"..\" (the "
                      "folder is [output] directory or -o)");
  }
  if (!gear && doc.HasSection("operating")) {
    doc.Problem("operating", "", "[operating] belongs to a gear case",
                "speeds and load of a [contact] case go in [contact]");
  }
  if (contact) {
    const auto t = doc.Reals("contact", "time_s");
    for (const char* key : {"load_table_n_per_m", "speed_1_table_m_s", "speed_2_table_m_s"}) {
      if (doc.Given("contact", key) && doc.Reals("contact", key).size() != t.size())
        doc.Problem("contact", key, "has " + std::to_string(doc.Reals("contact", key).size()) +
                    " entries but time_s has " + std::to_string(t.size()),
                    "one entry per time_s value");
    }
    for (size_t i = 1; i < t.size(); ++i)
      if (!(t[i] > t[i - 1])) {
        doc.Problem("contact", "time_s", "must increase strictly", "increasing times [s]");
        break;
      }
    if (doc.Int("contact", "steps") > 0 && t.size() < 2)
      doc.Problem("contact", "steps", "a transient run needs time tables",
                  "time_s with at least two entries, or steps = 0 for a steady solve");
    // A steady solve (steps = 0) runs at the scalar load and speeds: tables given with it
    // would be dropped without a word.
    if (doc.Int("contact", "steps") == 0 && doc.Given("contact", "time_s"))
      doc.Problem("contact", "steps",
                  "a steady solve at load_n_per_m and speed_*_m_s, but time_s and its "
                  "tables are given: they would not be used",
                  "steps > 0 to march through the tables, or no time_s and tables for a steady "
                  "solve");
    // Gear-cycle settings that a line contact has no use for: refused when set to anything
    // but their default (a study writes every default into its scenes).
    if (doc.Int("numerics", "steps") != 0)
      doc.Problem("numerics", "steps", "counts the time steps from A to E of a gear cycle",
                  "for a [contact] case, steps in [contact] (0 = steady)");
    if (!doc.Bool("output", "csv"))
      doc.Problem("output", "csv", "a [contact] run writes CSV files only",
                  "true (the default), or leave the key out");
    if (doc.Bool("output", "temperature_field"))
      doc.Problem("output", "temperature_field",
                  "the full T(x, z) goes into the HDF5 result of a gear cycle; a [contact] run "
                  "writes CSV files only",
                  "false (the default), or leave the key out");
  }

  const bool rough_effect = doc.Bool("effects", "roughness");
  for (const char* s : {"surfaces.surface1", "surfaces.surface2"}) {
    const std::string kind = doc.String(s, "roughness");
    // The keys of a form the surface does not have would be ignored without a word (a study
    // varying amplitude_m on a smooth surface ran identical scenes). Their defaults (0, "")
    // are what a written-out case (a study's scene) carries for every surface.
    const auto set = [&](const char* k) {
      if (!doc.Given(s, k)) return false;
      const std::string key = k;
      if (key == "profile_file") return !doc.String(s, k).empty();
      return key == "wavelength_m" || doc.Real(s, k) != 0.0;
    };
    const char* const sinusoidal_keys[] = {"amplitude_m", "wavelength_m", "phase_rad"};
    for (const char* k : sinusoidal_keys)
      if (set(k) && kind != "sinusoidal")
        doc.Problem(s, k,
                    "describes sinusoidal waviness, but the surface's roughness is \"" +
                        (kind.empty() ? std::string("smooth") : kind) + "\"",
                    "roughness = \"sinusoidal\" in this section, or leave the key out");
    if (set("profile_file") && kind != "profile")
      doc.Problem(s, "profile_file",
                  "is a measured profile, but the surface's roughness is \"" +
                      (kind.empty() ? std::string("smooth") : kind) + "\"",
                  "roughness = \"profile\" in this section, or leave the key out");
    if (kind.empty() || kind == "smooth") continue;
    if (!rough_effect)
      doc.Problem(s, "roughness", "a rough surface needs effects.roughness = true",
                  "roughness = \"smooth\", or set [effects] roughness = true");
    if (kind == "sinusoidal" && !doc.Given(s, "wavelength_m"))
      doc.Problem(s, "wavelength_m", "sinusoidal roughness needs a wavelength",
                  "a positive length [m]");
    if (kind == "profile" && doc.String(s, "profile_file").empty())
      doc.Problem(s, "profile_file", "a measured profile needs its file",
                  "a path to a two-column text file (x [m], height [m])");
  }

  if (doc.Has("lubricant", "name")) {
    const std::string name = doc.String("lubricant", "name");
    if (ResolveLubricantPath(name, path).empty())
      doc.Problem("lubricant", "name", "no such lubricant file", LubricantSearchText(path));
  }
  if (doc.Has("numerics", "grid_points")) {
    const long long n = doc.Int("numerics", "grid_points");
    if (n > 0 && n < 17)
      doc.Problem("numerics", "grid_points", "too few nodes for a film",
                  "0 (automatic) or an odd integer >= 17, e.g. 257, 513, 1025");
    else if (n > 0 && n % 2 == 0)
      doc.Problem("numerics", "grid_points", "must be odd, so a node sits at x = 0",
                  "0 (automatic) or an odd integer >= 17, e.g. 257, 513, 1025");
  }
  return doc;
}

}  // namespace tehl::internal
