#include "tehl/scene/path_point_case.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "io/atomic_file.hpp"
#include "scene/case_reader.hpp"
#include "scene/film_case.hpp"
#include "scene/gear_case.hpp"
#include "scene/mesh_cycle_plan.hpp"
#include "scene/study_case_text.hpp"
#include "tehl/error.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using internal::CaseOverride;
using internal::Document;
using internal::FormatShort;

constexpr const char* kAllowed =
    "A, B, C, D or E (B and D on their single-contact side), or a distance from A with its "
    "unit: 2.5mm or 0.0025m";

InputError BadPoint(const std::string& at, const std::string& rule, const std::string& allowed) {
  return InputError(InputProblem{"", 0, "--at", "\"" + at + "\"", rule, allowed});
}

struct Where {
  std::string label, tag;
  double s_m = 0;
  bool left = false;  // the one-sided limit from below (the load arriving there)
};

// "A" ... "E", or a length with the unit mm or m.
Where ParsePoint(const std::string& at, const PathOfContact& path) {
  std::string t;
  for (char ch : at)
    if (!std::isspace(static_cast<unsigned char>(ch))) t += ch;
  if (t.size() == 1) {
    const char p = static_cast<char>(std::toupper(static_cast<unsigned char>(t[0])));
    const std::string name(1, p);
    switch (p) {
      case 'A':
        return {name, name, 0.0, false};
      case 'B':
        return {name, name, path.s_b_m(), false};  // single contact begins
      case 'C':
        return {name, name, path.s_c_m(), false};
      case 'D':
        return {name, name, path.s_d_m(), true};  // single contact ends
      case 'E':
        return {name, name, path.length_m(), true};
      default:
        break;
    }
  }
  double scale = 0;
  std::string number;
  if (t.size() > 2 && t.compare(t.size() - 2, 2, "mm") == 0) {
    scale = 1e-3;
    number = t.substr(0, t.size() - 2);
  } else if (t.size() > 1 && t.back() == 'm') {
    scale = 1.0;
    number = t.substr(0, t.size() - 1);
  }
  double v = 0;
  size_t used = 0;
  bool parsed = false;
  if (scale > 0) try {
      v = std::stod(number, &used);
      parsed = used == number.size() && std::isfinite(v);
    } catch (const std::exception&) {
      parsed = false;
    }
  if (!parsed) throw BadPoint(at, "not a point of the path", kAllowed);
  const double s = v * scale, g = path.length_m();
  if (s < 0 || s > g * (1 + 1e-12))
    throw BadPoint(at, "outside the path of contact (A = 0 to E = " + FormatShort(g * 1e3) + " mm)",
                   "a distance from A from 0 to " + FormatShort(g * 1e3) + " mm");
  const std::string shown = number + (scale == 1e-3 ? " mm" : " m");
  return {"s = " + shown, "s" + number + (scale == 1e-3 ? "mm" : "m"), std::min(s, g),
          s >= g * (1 - 1e-12)};
}

std::string Literal(double v) { return internal::FormatValue(internal::Value(v)); }
std::string Literal(const std::string& v) { return internal::FormatValue(internal::Value(v)); }

}  // namespace

PathPointCase ContactCaseAtPoint(const std::string& gear_case_path,
                                 const std::string& at,
                                 const std::string& output_dir) {
  Document doc = internal::ReadCaseDocument(gear_case_path);
  if (doc.problems().empty() && !doc.HasSection("gear"))
    doc.Problem("gear", "", "a point of the path needs a [gear] pair (--at)",
                "a case with [gear], or `tehl run` without --at for a [contact] case");
  doc.ThrowIfProblems();
  std::optional<internal::GearCase> gear = internal::ReadGearCase(doc);
  internal::ReadFilmCase(doc);
  doc.ThrowIfProblems();
  if (!gear || !gear->pair) {  // ReadGearCase has reported why
    doc.Problem("gear", "", "the gear pair could not be built", "a valid gear pair");
    doc.ThrowIfProblems();
  }
  const internal::CyclePath cycle(*gear);
  const PathOfContact& path = cycle.path();
  const Where w = ParsePoint(at, path);
  const double g = path.length_m();
  if (w.s_m < cycle.begin_m() - 1e-9 * g || w.s_m > cycle.end_m() + 1e-9 * g)
    throw BadPoint(at,
                   "the tip relief unloads the pair there (it carries under " +
                       FormatShort(internal::kMinFilmShare * 100) + " % of F_bt)",
                   "a point where the pair is loaded: s from " +
                       FormatShort(cycle.begin_m() * 1e3) + " to " +
                       FormatShort(cycle.end_m() * 1e3) + " mm");
  const internal::PathState st = cycle.At(w.s_m, w.left);
  const ContactPoint& c = st.contact;

  PathPointCase out;
  out.label = w.label;
  out.tag = w.tag;
  out.s_m = w.s_m;
  out.path_length_m = g;
  out.reduced_radius_m = c.reduced_radius_m;
  out.load_n_per_m = st.load_n_per_m;
  out.load_share = st.static_load_n_per_m /
                   NominalToothLoad(*gear->pair, gear->operating).load_per_width_n_per_m;
  out.pairs_in_contact = c.pairs_in_contact;
  out.internal = path.internal();

  const fs::path dir =
      output_dir.empty() ? fs::path(doc.String("output", "directory")) : fs::path(output_dir);
  std::string name = doc.String("output", "name");
  if (name.empty()) name = fs::path(gear_case_path).stem().string();
  name += "_at_" + w.tag;
  out.case_path = (dir / (name + ".toml")).string();

  // Body 1 is the pinion, body 2 the wheel (a ring: a plane, its curvature in R).
  std::vector<CaseOverride> o;
  if (out.internal) {
    o.push_back({"contact.radius_1_m", Literal(c.reduced_radius_m)});
  } else {
    o.push_back({"contact.radius_1_m", Literal(c.rho1_m)});
    o.push_back({"contact.radius_2_m", Literal(c.rho2_m)});
  }
  // At C the flanks roll without sliding: both speeds are um there, not two products that
  // differ in their last bit.
  const bool pitch = w.label == "C";
  out.u1_m_s = pitch ? c.um_m_s : c.u1_m_s;
  out.u2_m_s = pitch ? c.um_m_s : c.u2_m_s;
  out.srr = pitch ? 0.0 : c.srr;
  o.push_back({"contact.speed_1_m_s", Literal(out.u1_m_s)});
  o.push_back({"contact.speed_2_m_s", Literal(out.u2_m_s)});
  o.push_back({"contact.load_n_per_m", Literal(st.load_n_per_m)});
  const std::pair<const char*, const char*> keys[] = {{"youngs_modulus", "pa"},
                                                      {"poisson_ratio", ""},
                                                      {"density", "kg_m3"},
                                                      {"conductivity", "w_mk"},
                                                      {"heat_capacity", "j_kgk"}};
  for (int body : {1, 2}) {
    const char* gear_section = body == 1 ? "gear.pinion" : "gear.wheel";
    for (const auto& [stem, unit] : keys) {
      const std::string gear_key = std::string(stem) + (*unit ? "_" : "") + unit;
      const std::string key =
          std::string(stem) + "_" + std::to_string(body) + (*unit ? "_" : "") + unit;
      o.push_back({"contact." + key, Literal(doc.Real(gear_section, gear_key))});
    }
  }
  o.push_back({"contact.steps", "0"});
  // The load is already the dynamic one when the effect is on; [numerics] steps is the
  // cycle's.
  o.push_back({"effects.dynamic_load", "false"});
  o.push_back({"numerics.steps", "0"});
  o.push_back({"output.directory", Literal(fs::absolute(dir).lexically_normal().string())});
  o.push_back({"output.name", Literal(name)});
  internal::AddPathOverrides(doc, gear_case_path, &o);

  char head[1024];
  std::snprintf(head, sizeof head,
                "# The steady film at %s of the gear case %s (tehl run --at %s):\n"
                "# s = %.6g mm from A (A..E = %.6g mm), %d pair(s) in contact, SRR %+.4f,\n"
                "# load %.6g N/m = %.4f F_bt/b%s.\n"
                "# Body 1 is the pinion's flank, body 2 the wheel's%s.\n",
                w.label.c_str(), fs::absolute(gear_case_path).lexically_normal().c_str(),
                at.c_str(), w.s_m * 1e3, g * 1e3, c.pairs_in_contact, out.srr, st.load_n_per_m,
                out.load_share,
                gear->dynamic_load ? " static share (the load is the dynamic one)" : "",
                out.internal ? " (an internal ring: a plane here, its concave curvature in "
                               "radius_1_m = R)"
                             : "");
  std::string text = doc.ToToml();
  text = text.substr(text.find('\n') + 1);  // the "as run" line names the gear case
  text = internal::RemoveCaseSections(
      text, {"gear", "gear.pinion", "gear.wheel", "operating", "dynamics", "motor"});
  text = internal::ApplyCaseOverrides("[contact]\n" + text, o);
  out.case_text = head + text;
  return out;
}

PathPointCase WriteContactCaseAtPoint(const std::string& gear_case_path,
                                      const std::string& at,
                                      const std::string& output_dir) {
  PathPointCase out = ContactCaseAtPoint(gear_case_path, at, output_dir);
  internal::WriteTextAtomically(out.case_path, out.case_text);
  return out;
}

}  // namespace tehl
