// Checking a TOML text against its Schema (Document::ReadString): every key checked for kind,
// range and choices, defaults filled, every problem collected with file and line (schema.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <toml.hpp>

#include "base/schema.hpp"
#include "base/toml_guard.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {
namespace {

std::string JoinNames(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "none" : s;
}

std::string ShowToml(const toml::value& v) {
  if (v.is_string()) return "\"" + v.as_string().str + "\"";
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_floating()) return FormatReal(v.as_floating());
  if (v.is_boolean()) return v.as_boolean() ? "true" : "false";
  if (v.is_table()) return "{table}";
  if (v.is_array()) {
    std::string s = "[";
    const auto& a = v.as_array();
    for (size_t i = 0; i < a.size() && i < 8; ++i) s += (i ? ", " : "") + ShowToml(a[i]);
    if (a.size() > 8) s += ", ...";
    return s + "]";
  }
  std::ostringstream o;
  o << v;
  std::string s = o.str();
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

bool InRange(const KeySpec& k, double x) {
  if (!std::isfinite(x)) return false;
  if (k.min && (k.min_inclusive ? x < *k.min : x <= *k.min)) return false;
  if (k.max && (k.max_inclusive ? x > *k.max : x >= *k.max)) return false;
  return true;
}

// Parses a TOML literal from a schema default (a programming error if it fails).
Value ParseDefault(const KeySpec& k) {
  if (k.default_toml.empty()) return std::monostate{};
  std::istringstream in("x = " + k.default_toml);
  const toml::value doc = toml::parse(in, "<default>");
  const toml::value& v = doc.as_table().at("x");
  switch (k.kind) {
    case ValueKind::kBool:
      return v.as_boolean();
    case ValueKind::kInt:
      return static_cast<long long>(v.as_integer());
    case ValueKind::kDouble:
      return v.is_integer() ? static_cast<double>(v.as_integer()) : v.as_floating();
    case ValueKind::kString:
      return v.as_string().str;
    case ValueKind::kDoubleArray: {
      std::vector<double> out;
      for (const auto& e : v.as_array())
        out.push_back(e.is_integer() ? static_cast<double>(e.as_integer()) : e.as_floating());
      return out;
    }
  }
  return std::monostate{};
}

}  // namespace

// ---------------------------------------------------------------------------------------
class DocumentReader {
 public:
  DocumentReader(const Schema& schema, Document* doc) : schema_(schema), doc_(*doc) {}

  void Read(const toml::value& root) {
    if (!root.is_table()) return;
    const SectionSpec* top = schema_.Find("");
    ReadTable(root.as_table(), "", top, 0);
    // Defaults for required sections that are missing, and missing-section problems.
    for (const auto& sec : schema_.sections) {
      const bool present = sec.name.empty() || doc_.section_lines_.count(sec.name);
      if (!present && sec.required) {
        Add(0, "[" + sec.name + "]", "", "required section is missing",
            "a [" + sec.name + "] table: " + sec.meaning);
      }
      // An absent optional section with no required key is all defaults: fill it, so
      // [numerics] or [effects] may be left out entirely.
      bool all_default = true;
      for (const auto& k : sec.keys) all_default = all_default && !k.required;
      if (present || sec.required || all_default) FillDefaults(sec);
    }
  }

 private:
  void Add(int line, std::string key, std::string value, std::string rule, std::string allowed) {
    doc_.problems_.Add(
        {doc_.path_, line, std::move(key), std::move(value), std::move(rule), std::move(allowed)});
  }

  static std::vector<std::pair<std::string, const toml::value*>> ByLine(const toml::table& t) {
    std::vector<std::pair<std::string, const toml::value*>> items;
    for (const auto& [k, v] : t) items.emplace_back(k, &v);
    std::sort(items.begin(), items.end(), [](const auto& a, const auto& b) {
      const auto la = a.second->location().line(), lb = b.second->location().line();
      return la != lb ? la < lb : a.first < b.first;
    });
    return items;
  }

  std::vector<std::string> ChildSections(const std::string& prefix) const {
    std::vector<std::string> out;
    for (const auto& s : schema_.sections) {
      if (s.name.empty()) continue;
      const std::string p = prefix.empty() ? "" : prefix + ".";
      if (s.name.rfind(p, 0) == 0 && s.name.find('.', p.size()) == std::string::npos)
        out.push_back("[" + s.name + "]");
    }
    return out;
  }

  void ReadTable(const toml::table& t, const std::string& name, const SectionSpec* spec, int line) {
    if (!name.empty()) doc_.section_lines_[name] = line;
    for (const auto& [key, vp] : ByLine(t)) {
      const toml::value& v = *vp;
      const int vline = static_cast<int>(v.location().line());
      const std::string full = name.empty() ? key : name + "." + key;
      if (v.is_table()) {
        if (const SectionSpec* sub = schema_.Find(full)) {
          ReadTable(v.as_table(), full, sub, vline);
          continue;
        }
      }
      const KeySpec* k = spec ? spec->Find(key) : nullptr;
      if (!k) {
        if (v.is_table()) {
          const std::vector<std::string> sections = ChildSections(name);  // "[name]"
          std::vector<std::string> bare;
          for (const std::string& c : sections) bare.push_back(c.substr(1, c.size() - 2));
          const std::string near = NearestName(full, bare);
          Add(vline, "[" + full + "]", "",
              near.empty() ? std::string("unknown section")
                           : "unknown section (did you mean [" + near + "]?)",
              "known sections: " + JoinNames(sections));
        } else {
          std::vector<std::string> known;
          if (spec)
            for (const auto& kk : spec->keys) known.push_back(kk.name);
          const std::string near = NearestName(key, known);
          Add(vline, full, ShowToml(v),
              near.empty() ? std::string("unknown key")
                           : "unknown key (did you mean " + near + "?)",
              (name.empty() ? std::string("top-level keys: ") : "keys of [" + name + "]: ") +
                  JoinNames(known));
        }
        continue;
      }
      ReadValue(*k, full, v, vline);
    }
  }

  bool Number(const toml::value& v, double* x) {
    if (v.is_integer()) {
      *x = static_cast<double>(v.as_integer());
      return true;
    }
    if (v.is_floating()) {
      *x = v.as_floating();
      return true;
    }
    return false;
  }

  void ReadValue(const KeySpec& k, const std::string& full, const toml::value& v, int line) {
    Document::Entry e;
    e.line = line;
    e.given = true;
    const std::string shown = ShowToml(v);
    auto wrong_type = [&] {
      Add(line, full, shown, "wrong type: expected " + KindName(k.kind), AllowedText(k));
    };
    auto range_problem = [&](double x) {
      std::string rule = "out of range: must be " + RangeText(k) + UnitSuffix(k.unit);
      if (k.unit == "K" && x < kMinAbsoluteTemperatureK && x > -273.15)
        rule += " (did you give degrees Celsius?)";
      if (k.unit == "Pa" && k.min == kMinModulusPa && x > 0 && x < kMinModulusPa)
        rule += " (did you give GPa or MPa? steel is 206e9 Pa)";
      if (k.min && x < *k.min && x > 0) rule += k.below_hint;
      if (k.max && x > *k.max) rule += k.above_hint;
      // A 0 for "none" where leaving the key out says it (radius_2_m: absent = a flat plane).
      if (const size_t a = k.meaning.find("absent = "); x == 0 && a != std::string::npos)
        rule += " (" + k.meaning.substr(a) + ": leave the key out)";
      if (!std::isfinite(x)) rule = "must be a finite number";
      Add(line, full, shown, rule, AllowedText(k));
    };
    switch (k.kind) {
      case ValueKind::kBool:
        if (!v.is_boolean()) return wrong_type();
        e.value = v.as_boolean();
        break;
      case ValueKind::kInt: {
        if (!v.is_integer()) {
          double x = 0;
          if (Number(v, &x) && std::isfinite(x) && x == std::floor(x))
            return Add(line, full, shown, "must be written as an integer (no decimal point)",
                       AllowedText(k));
          return wrong_type();
        }
        const long long i = v.as_integer();
        if (!InRange(k, static_cast<double>(i))) return range_problem(static_cast<double>(i));
        e.value = i;
        break;
      }
      case ValueKind::kDouble: {
        double x = 0;
        if (!Number(v, &x)) return wrong_type();
        if (!InRange(k, x)) return range_problem(x);
        e.value = x;
        break;
      }
      case ValueKind::kString: {
        if (!v.is_string()) return wrong_type();
        const std::string s = v.as_string().str;
        if (!k.choices.empty() &&
            std::find(k.choices.begin(), k.choices.end(), s) == k.choices.end())
          return Add(line, full, shown, "unknown value", AllowedText(k));
        e.value = s;
        break;
      }
      case ValueKind::kDoubleArray: {
        if (!v.is_array()) return wrong_type();
        std::vector<double> a;
        for (const auto& el : v.as_array()) {
          double x = 0;
          if (!Number(el, &x)) return wrong_type();
          if (!InRange(k, x)) return range_problem(x);
          a.push_back(x);
        }
        e.value = std::move(a);
        break;
      }
    }
    doc_.entries_[full] = std::move(e);
  }

  void FillDefaults(const SectionSpec& sec) {
    for (const auto& k : sec.keys) {
      const std::string full = Document::FullKey(sec.name, k.name);
      if (doc_.entries_.count(full)) continue;
      if (k.required) {
        // A key given with a bad value was already reported; report only absent ones.
        if (!Written(sec.name, k.name)) {
          const auto it = doc_.section_lines_.find(sec.name);
          Add(it == doc_.section_lines_.end() ? 0 : it->second, full, "", "required key is missing",
              AllowedText(k) + ", e.g. " + k.name + " = " + k.example);
        }
        continue;
      }
      Document::Entry e;
      e.value = ParseDefault(k);
      if (!std::holds_alternative<std::monostate>(e.value)) doc_.entries_[full] = std::move(e);
    }
  }

  bool Written(const std::string& section, const std::string& key) const {
    const std::string full = Document::FullKey(section, key);
    for (const auto& p : doc_.problems_.problems())
      if (p.key == full) return true;
    return false;
  }

  const Schema& schema_;
  Document& doc_;
};

Document Document::ReadString(const Schema& schema,
                              const std::string& text,
                              const std::string& name) {
  Document doc;
  doc.schema_ = &schema;
  doc.path_ = name;
  if (const TomlTextProblem bad = FindUnsafeTomlText(text); bad.line > 0) {
    doc.problems_.Add({name, bad.line, "(syntax)", "", "not read: " + bad.what, bad.allowed});
    return doc;
  }
  toml::value root;
  try {
    std::istringstream in(text);
    root = toml::parse(in, name);
  } catch (const toml::exception& e) {
    std::string msg = e.what();
    // toml11 prints "[error] toml::parse_...: <reason>\n --> file\n ..." : keep the reason.
    const auto nl = msg.find('\n');
    if (nl != std::string::npos) msg = msg.substr(0, nl);
    const auto colon = msg.find(": ");
    if (msg.rfind("[error]", 0) == 0 && colon != std::string::npos) msg = msg.substr(colon + 2);
    doc.problems_.Add({name, static_cast<int>(e.location().line()), "(syntax)", "",
                       "not valid TOML: " + msg, "a TOML document (https://toml.io)"});
    return doc;
  } catch (const std::exception& e) {
    doc.problems_.Add({name, 0, "(file)", "", std::string("cannot be read as TOML: ") + e.what(),
                       "a UTF-8 TOML text file"});
    return doc;
  }
  DocumentReader(schema, &doc).Read(root);
  return doc;
}

}  // namespace tehl::internal
