// Input schemas: key specifications, their text in messages and `--print-default`, and
// number formatting (schema.hpp; reading a file against a schema is document.cpp and
// document_reader.cpp).
#include "base/schema.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "tehl/units.hpp"

namespace tehl::internal {

std::string KindName(ValueKind k) {
  switch (k) {
    case ValueKind::kBool: return "a boolean (true or false)";
    case ValueKind::kInt: return "an integer";
    case ValueKind::kDouble: return "a number";
    case ValueKind::kString: return "a string";
    case ValueKind::kDoubleArray: return "an array of numbers";
  }
  return "?";
}

std::string UnitSuffix(const std::string& unit) {
  if (unit.empty() || unit == "-") return "";
  return " [" + unit + "]";
}

std::string RangeText(const KeySpec& k) {
  auto num = [&](double x) {
    return k.kind == ValueKind::kInt ? std::to_string(static_cast<long long>(x)) : FormatReal(x);
  };
  std::string s;
  if (k.min) s += (k.min_inclusive ? ">= " : "> ") + num(*k.min);
  if (k.max) {
    if (!s.empty()) s += " and ";
    s += (k.max_inclusive ? "<= " : "< ") + num(*k.max);
  }
  return s;
}

std::string AllowedText(const KeySpec& k) {
  if (!k.choices.empty()) {
    std::string s = "one of ";
    for (size_t i = 0; i < k.choices.size(); ++i) s += (i ? ", \"" : "\"") + k.choices[i] + "\"";
    return s;
  }
  std::string s = KindName(k.kind);
  const std::string r = RangeText(k);
  if (!r.empty()) s += " " + r;
  return s + UnitSuffix(k.unit);
}

// The known name within two edits (insertions, deletions, substitutions) of `name`, the
// closest first; "" when none is that close or the name is short enough for two edits to
// reach anything.
std::string NearestName(const std::string& name, const std::vector<std::string>& known) {
  if (name.size() < 4) return "";
  auto distance = [](const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
      size_t diag = row[0];
      row[0] = i;
      for (size_t j = 1; j <= b.size(); ++j) {
        const size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diag = up;
      }
    }
    return row[b.size()];
  };
  std::string best;
  size_t best_d = 3;
  for (const std::string& k : known) {
    const size_t d = distance(name, k);
    if (d < best_d) {
      best_d = d;
      best = k;
    }
  }
  return best;
}

std::string FormatValue(const Value& v) {
  struct V {
    std::string operator()(std::monostate) const { return ""; }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(long long i) const { return std::to_string(i); }
    std::string operator()(double d) const { return FormatReal(d); }
    std::string operator()(const std::string& s) const {
      std::string q = "\"";
      for (char c : s) {
        if (c == '"' || c == '\\') q += '\\';
        q += c;
      }
      return q + "\"";
    }
    std::string operator()(const std::vector<double>& a) const {
      std::string s = "[";
      for (size_t i = 0; i < a.size(); ++i) s += (i ? ", " : "") + FormatReal(a[i]);
      return s + "]";
    }
  };
  return std::visit(V{}, v);
}

const KeySpec* SectionSpec::Find(std::string_view key) const {
  for (const auto& k : keys)
    if (k.name == key) return &k;
  return nullptr;
}

const SectionSpec* Schema::Find(std::string_view section) const {
  for (const auto& s : sections)
    if (s.name == section) return &s;
  return nullptr;
}

std::string Schema::PrintDefaults() const {
  std::ostringstream o;
  o << "# Every key of a tehl " << kind << " file with its default, unit and meaning.\n"
    << "# Keys marked (required) have no default: the value shown is an example.\n";
  for (const auto& sec : sections) {
    o << "\n";
    if (!sec.name.empty()) o << "[" << sec.name << "]";
    o << (sec.name.empty() ? "# " : "  # ") << sec.meaning
      << (sec.required ? " (required section)" : " (optional section)") << "\n";
    for (const auto& k : sec.keys) {
      std::string lhs;
      const std::string& val = k.default_toml.empty() ? k.example : k.default_toml;
      if (val.empty())
        lhs = "# " + k.name + " =";  // optional key without default: commented out
      else
        lhs = k.name + " = " + val;
      o << lhs;
      for (size_t pad = lhs.size(); pad < 40; ++pad) o << ' ';
      o << " # " << (k.unit.empty() ? "" : "[" + k.unit + "] ") << k.meaning;
      if (k.required) o << " (required)";
      if (!k.choices.empty() || k.min || k.max) o << "; allowed: " << AllowedText(k);
      o << "\n";
    }
  }
  return o.str();
}

KeySpec Real(std::string name, std::string unit, std::string def, std::string meaning,
             std::optional<double> min, std::optional<double> max, bool min_inc, bool max_inc) {
  KeySpec k;
  k.name = std::move(name);
  k.kind = ValueKind::kDouble;
  k.unit = std::move(unit);
  k.default_toml = std::move(def);
  k.meaning = std::move(meaning);
  k.min = min;
  k.max = max;
  k.min_inclusive = min_inc;
  k.max_inclusive = max_inc;
  return k;
}

KeySpec Positive(std::string name, std::string unit, std::string def, std::string meaning) {
  return Real(std::move(name), std::move(unit), std::move(def), std::move(meaning), 0.0,
              std::nullopt, false);
}

KeySpec Integer(std::string name, std::string unit, std::string def, std::string meaning,
                std::optional<double> min, std::optional<double> max) {
  KeySpec k = Real(std::move(name), std::move(unit), std::move(def), std::move(meaning), min, max);
  k.kind = ValueKind::kInt;
  return k;
}

KeySpec Flag(std::string name, std::string def, std::string meaning) {
  KeySpec k;
  k.name = std::move(name);
  k.kind = ValueKind::kBool;
  k.default_toml = std::move(def);
  k.meaning = std::move(meaning);
  return k;
}

KeySpec Text(std::string name, std::string def, std::string meaning,
             std::vector<std::string> choices) {
  KeySpec k;
  k.name = std::move(name);
  k.kind = ValueKind::kString;
  k.default_toml = std::move(def);
  k.meaning = std::move(meaning);
  k.choices = std::move(choices);
  return k;
}

KeySpec Reals(std::string name,
              std::string unit,
              std::string def,
              std::string meaning,
              std::optional<double> min,
              std::optional<double> max) {
  KeySpec k = Real(std::move(name), std::move(unit), std::move(def), std::move(meaning), min, max);
  k.kind = ValueKind::kDoubleArray;
  return k;
}

KeySpec Temperature(std::string name, std::string def, std::string meaning) {
  // Absolute temperatures only: anything below 200 K is almost surely degrees Celsius.
  return Real(std::move(name), "K", std::move(def), std::move(meaning), kMinAbsoluteTemperatureK,
              kMaxTemperatureK);
}

KeySpec Modulus(std::string name, std::string def, std::string meaning) {
  // Young's moduli of engineering solids, from soft elastomers (about 1 MPa) to diamond
  // (1.2e12 Pa): a value below 1e6 Pa is almost surely given in GPa or MPa.
  return Real(std::move(name), "Pa", std::move(def), std::move(meaning), kMinModulusPa, 2e12);
}

namespace {
KeySpec WithHints(KeySpec k, std::string below, std::string above) {
  k.below_hint = std::move(below);
  k.above_hint = std::move(above);
  return k;
}
}  // namespace

// Ranges: polymers (PTFE 0.25 W/(m K), 1000-2200 kg/m^3, c up to about 2000 J/(kg K)) to
// tungsten carbide (15600 kg/m^3), copper (400 W/(m K)) and diamond (about 2000 W/(m K)).
KeySpec SolidDensity(std::string name, std::string def, std::string meaning) {
  return WithHints(
      Real(std::move(name), "kg/m^3", std::move(def), std::move(meaning), 500.0, 25000.0),
      " (did you give g/cm^3? steel is 7850 kg/m^3)", " (steel is 7850 kg/m^3)");
}

KeySpec SolidConductivity(std::string name, std::string def, std::string meaning) {
  return WithHints(
      Real(std::move(name), "W/(m K)", std::move(def), std::move(meaning), 0.05, 2000.0),
      " (did you give W/(mm K)? steel is 46 W/(m K))", " (steel is 46 W/(m K))");
}

KeySpec SolidHeatCapacity(std::string name, std::string def, std::string meaning) {
  return WithHints(
      Real(std::move(name), "J/(kg K)", std::move(def), std::move(meaning), 100.0, 5000.0),
      " (did you give kJ/(kg K)? steel is 470 J/(kg K))", " (steel is 470 J/(kg K))");
}

KeySpec Required(KeySpec k, std::string example) {
  k.required = true;
  k.example = std::move(example);
  k.default_toml.clear();
  return k;
}

}  // namespace tehl::internal
