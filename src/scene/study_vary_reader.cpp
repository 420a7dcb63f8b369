// One [[vary]] entry of a study file (study_vary_reader.hpp): the case key it varies (a key of
// the case schema, not the output's folder or name), its label, and its values, as a list or
// as a from/to/count range (linear or logarithmic).
#include "scene/study_vary_reader.hpp"

#include <cmath>
#include <set>

#include "base/schema.hpp"
#include "tehl/scene/case_schema.hpp"

namespace tehl::internal {

std::string ShowStudyValue(const toml::value& v) {
  if (v.is_string()) return FormatValue(Value(v.as_string().str));
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_floating()) return FormatReal(v.as_floating());
  if (v.is_boolean()) return v.as_boolean() ? "true" : "false";
  if (v.is_array()) return "[...]";
  if (v.is_table()) return "{table}";
  return "?";
}

int TomlLine(const toml::value& v) { return static_cast<int>(v.location().line()); }

namespace {

class VaryReader {
 public:
  VaryReader(const std::string& path, ProblemList* problems) : path_(path), problems_(*problems) {}

  void Add(int line, std::string key, std::string value, std::string rule, std::string allowed) {
    problems_.Add(
        {path_, line, std::move(key), std::move(value), std::move(rule), std::move(allowed)});
  }

  // Reads one [[vary]] table (number `n`, 1-based, for messages).
  std::optional<StudyParameter> Read(const toml::value& t, int n, int table_line) {
    const std::string where = "vary[" + std::to_string(n) + "]";
    StudyParameter p;
    p.line = table_line;
    bool ok = true;
    static const std::set<std::string> known = {"key",   "values", "from", "to",
                                                "count", "log",    "label"};
    for (const auto& [k, v] : t.as_table())
      if (!known.count(k)) {
        Add(TomlLine(v), where + "." + k, ShowStudyValue(v), "unknown key",
            "keys of [[vary]]: key, values, from, to, count, log, label");
        ok = false;
      }
    const auto& tab = t.as_table();
    auto get = [&](const char* k) -> const toml::value* {
      const auto it = tab.find(k);
      return it == tab.end() ? nullptr : &it->second;
    };
    const KeySpec* spec = nullptr;
    if (const toml::value* key = get("key"); !key || !key->is_string()) {
      Add(key ? TomlLine(*key) : table_line, where + ".key", key ? ShowStudyValue(*key) : "",
          key ? "wrong type: expected a string" : "required key is missing",
          "a dotted case key, e.g. key = \"surfaces.surface1.amplitude_m\"");
      return std::nullopt;
    } else {
      p.key = key->as_string().str;
      p.line = TomlLine(*key);
      spec = CaseKey(p.key, where, p.line);
      if (!spec) return std::nullopt;
      p.unit = spec->unit;
    }
    p.label = p.key;
    if (const toml::value* label = get("label")) {
      const std::string text = label->is_string() ? label->as_string().str : std::string();
      // A label names an index column, an HDF5 dataset and a figure file (study_<label>.png
      // beside study_path.png and study_path_<q>.png of tehl plot).
      const bool plain = !text.empty() && text.find_first_not_of(
                                              "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQ"
                                              "RSTUVWXYZ0123456789_.-") == std::string::npos;
      const bool plot_name = text == "path" || text.rfind("path_", 0) == 0;
      if (plain && !plot_name)
        p.label = text;
      else
        Add(TomlLine(*label), where + ".label", ShowStudyValue(*label),
            !label->is_string() || text.empty() ? "must be a non-empty string"
            : plot_name ? "is the name of the path figures of tehl plot (study_path*.png)"
                        : "must be letters, digits, _, . and - only (it names a column, "
                          "an HDF5 dataset and a figure file)",
            "a column name for the index, e.g. label = \"amplitude\"");
    }
    const toml::value* values = get("values");
    const bool range = get("from") || get("to") || get("count") || get("log");
    if (values && range) {
      Add(TomlLine(*values), where + ".values", "[...]", "give values or a range, not both",
          "values = [...], or from, to, count (and log = true)");
      return std::nullopt;
    }
    if (!values && !range) {
      Add(p.line, where + ".values", "", "the values are missing",
          "values = [...], or from, to, count (and log = true)");
      return std::nullopt;
    }
    if (values) {
      p.values_line = TomlLine(*values);
      ok = ReadList(*values, *spec, where, &p) && ok;
    } else {
      ok = ReadRange(tab, *spec, where, &p) && ok;
    }
    if (!ok) return std::nullopt;
    return p;
  }

 private:
  const KeySpec* CaseKey(const std::string& dotted, const std::string& where, int line) {
    const auto dot = dotted.rfind('.');
    const std::string section = dot == std::string::npos ? "" : dotted.substr(0, dot);
    const std::string key = dot == std::string::npos ? dotted : dotted.substr(dot + 1);
    const SectionSpec* sec = CaseSchema().Find(section);
    const KeySpec* k = sec ? sec->Find(key) : nullptr;
    if (!k) {
      std::string allowed;
      if (sec && !section.empty()) {
        allowed = "keys of [" + section + "]:";
        for (const auto& kk : sec->keys) allowed += " " + kk.name;
      } else {
        allowed =
            "a key of a case section (docs/case_format.md), e.g. "
            "\"surfaces.surface1.amplitude_m\"; sections:";
        for (const auto& s : CaseSchema().sections)
          if (!s.name.empty() && !s.keys.empty()) allowed += " " + s.name;
      }
      Add(line, where + ".key", FormatValue(Value(dotted)), "unknown case key", allowed);
      return nullptr;
    }
    if (section == "output" && (key == "directory" || key == "name")) {
      Add(line, where + ".key", FormatValue(Value(dotted)),
          "set by the study for each scene (<output>/scenes/scene_NNNN)",
          "any case key except output.directory and output.name");
      return nullptr;
    }
    return k;
  }

  // One value of a list, as a TOML literal for the case key `spec`.
  bool AddValue(const toml::value& v, const KeySpec& spec, StudyParameter* p) {
    if (v.is_integer() && spec.kind == ValueKind::kDouble) {
      p->values_toml.push_back(FormatReal(static_cast<double>(v.as_integer())));
    } else if (v.is_array()) {
      std::vector<double> a;
      for (const auto& e : v.as_array()) {
        if (e.is_integer())
          a.push_back(static_cast<double>(e.as_integer()));
        else if (e.is_floating())
          a.push_back(e.as_floating());
        else
          return false;
      }
      p->values_toml.push_back(FormatValue(Value(a)));
      p->numeric = false;
      return true;
    } else {
      p->values_toml.push_back(ShowStudyValue(v));
    }
    if (v.is_integer())
      p->values_number.push_back(static_cast<double>(v.as_integer()));
    else if (v.is_floating())
      p->values_number.push_back(v.as_floating());
    else
      p->numeric = false;
    return true;
  }

  bool ReadList(const toml::value& values,
                const KeySpec& spec,
                const std::string& where,
                StudyParameter* p) {
    const std::string allowed =
        "a non-empty array of numbers, strings or booleans (one per scene), e.g. "
        "values = [1e-7, 2e-7]";
    if (!values.is_array() || values.as_array().empty()) {
      Add(TomlLine(values), where + ".values", ShowStudyValue(values),
          values.is_array() ? "must not be empty" : "wrong type: expected an array", allowed);
      return false;
    }
    const auto& a = values.as_array();
    for (size_t i = 0; i < a.size(); ++i) {
      const bool scalar = a[i].is_integer() || a[i].is_floating() || a[i].is_string() ||
                          a[i].is_boolean() || a[i].is_array();
      if (!scalar || !AddValue(a[i], spec, p) ||
          (a[i].is_floating() && !std::isfinite(a[i].as_floating()))) {
        Add(TomlLine(values), where + ".values[" + std::to_string(i) + "]", ShowStudyValue(a[i]),
            "not a usable value", allowed);
        return false;
      }
    }
    if (!p->numeric) p->values_number.clear();
    return true;
  }

  bool ReadRange(const toml::table& t,
                 const KeySpec& spec,
                 const std::string& where,
                 StudyParameter* p) {
    const std::string allowed =
        "from = <number>, to = <number>, count = <integer >= 2>, "
        "optional log = true (from, to > 0)";
    auto number = [&](const char* k, double* x) {
      const auto it = t.find(k);
      if (it == t.end()) {
        Add(p->line, where + "." + k, "", "required key of a range is missing", allowed);
        return false;
      }
      const toml::value& v = it->second;
      if (!p->values_line || std::string(k) == "from") p->values_line = TomlLine(v);
      if (v.is_integer())
        *x = static_cast<double>(v.as_integer());
      else if (v.is_floating() && std::isfinite(v.as_floating()))
        *x = v.as_floating();
      else {
        Add(TomlLine(v), where + "." + k, ShowStudyValue(v), "must be a finite number", allowed);
        return false;
      }
      return true;
    };
    double from = 0, to = 0, count_d = 0;
    bool ok = number("from", &from) & number("to", &to);
    const auto c = t.find("count");
    long long count = 0;
    if (c == t.end()) {
      Add(p->line, where + ".count", "", "required key of a range is missing", allowed);
      ok = false;
    } else if (!c->second.is_integer() || c->second.as_integer() < 2 ||
               c->second.as_integer() > kMaxStudyScenes) {
      Add(TomlLine(c->second), where + ".count", ShowStudyValue(c->second),
          "must be an integer from 2 to " + std::to_string(kMaxStudyScenes), allowed);
      ok = false;
    } else {
      count = c->second.as_integer();
    }
    (void)count_d;
    bool log = false;
    if (const auto l = t.find("log"); l != t.end()) {
      if (!l->second.is_boolean()) {
        Add(TomlLine(l->second), where + ".log", ShowStudyValue(l->second),
            "wrong type: expected a boolean", allowed);
        ok = false;
      } else {
        log = l->second.as_boolean();
      }
    }
    if (ok && log && !(from > 0 && to > 0)) {
      Add(p->values_line, where + ".from", FormatReal(from),
          "a logarithmic range needs from > 0 and to > 0", allowed);
      ok = false;
    }
    if (ok && spec.kind != ValueKind::kDouble && spec.kind != ValueKind::kInt) {
      Add(p->line, where + ".key", FormatValue(Value(p->key)), "a range needs a numeric case key",
          "values = [...] for this key");
      ok = false;
    }
    if (ok && from == to) {
      Add(p->values_line, where + ".to", FormatReal(to),
          "equals from: the range would give " + std::to_string(count) + " identical scenes",
          "to != from, or values = [" + FormatReal(from) + "] for one scene");
      ok = false;
    }
    if (!ok) return false;
    for (long long i = 0; i < count; ++i) {
      const double f = static_cast<double>(i) / static_cast<double>(count - 1);
      double x = log ? std::exp(std::log(from) + f * (std::log(to) - std::log(from)))
                     : from + f * (to - from);
      if (i == 0) x = from;  // both end points exactly as written
      if (i == count - 1) x = to;
      if (spec.kind == ValueKind::kInt) {
        x = std::round(x);  // integer keys: the nearest integer (docs/studies.md)
        p->values_toml.push_back(std::to_string(static_cast<long long>(x)));
      } else {
        p->values_toml.push_back(FormatReal(x));
      }
      p->values_number.push_back(x);
    }
    return true;
  }

  const std::string& path_;
  ProblemList& problems_;
};

}  // namespace

std::optional<StudyParameter> ReadVaryTable(
    const std::string& path, const toml::value& t, int n, int table_line, ProblemList* problems) {
  return VaryReader(path, problems).Read(t, n, table_line);
}

}  // namespace tehl::internal
