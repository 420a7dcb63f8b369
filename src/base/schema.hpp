// Declarative schemas for tehl's TOML input files (case, lubricant, study, train), in the
// spirit of deal.II's ParameterHandler: only declared keys are accepted, each with a type, a
// unit, a range and a one-line meaning. Reading a file collects every problem in one pass,
// each with file:line, key, value, rule and what is allowed (tehl/error.hpp). The same
// schema prints the documented defaults (`tehl case --print-default`) and writes the document
// back as run, defaults filled (HDF5 /case).
//
// Private to src/: toml11 stays out of the public headers.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "base/number_text.hpp"
#include "tehl/error.hpp"

namespace tehl::internal {

enum class ValueKind { kBool, kInt, kDouble, kString, kDoubleArray };

struct KeySpec {
  std::string name;                  // key inside its section, e.g. "module_m"
  ValueKind kind = ValueKind::kDouble;
  std::string unit;                  // "m", "Pa", "K", "-" for dimensionless, "" for text
  std::string meaning;               // one line, shown by --print-default
  std::string default_toml;          // TOML literal of the default; "" means no default
  bool required = false;             // must be written in the file
  std::optional<double> min, max;    // numeric range (also bounds each array element)
  bool min_inclusive = true;
  bool max_inclusive = true;
  std::vector<std::string> choices;  // allowed strings (kString); empty = any
  std::string example;               // shown by --print-default when there is no default
  // Added to an out-of-range message below min / above max: the likely unit slip, e.g.
  // " (did you give g/cm^3? steel is 7850 kg/m^3)"; "" = none.
  std::string below_hint, above_hint;
};

struct SectionSpec {
  std::string name;                  // "" for top-level keys, "gear", or nested "gear.pinion"
  std::string meaning;
  bool required = false;
  std::vector<KeySpec> keys;
  const KeySpec* Find(std::string_view key) const;
};

struct Schema {
  std::string kind;                  // "case", "lubricant", ... for messages
  std::vector<SectionSpec> sections;
  const SectionSpec* Find(std::string_view section) const;
  // Every key with its default, unit and meaning, as a commented TOML file.
  std::string PrintDefaults() const;
};

// Builders that keep schema tables short and readable.
// The longest input file read (case, lubricant, study, train files): 16 MiB [bytes].
inline constexpr std::uintmax_t kMaxInputFileBytes = 16u << 20;

KeySpec Real(std::string name, std::string unit, std::string default_toml, std::string meaning,
             std::optional<double> min = std::nullopt, std::optional<double> max = std::nullopt,
             bool min_inclusive = true, bool max_inclusive = true);
KeySpec Positive(std::string name, std::string unit, std::string default_toml,
                 std::string meaning);  // > 0
KeySpec Integer(std::string name, std::string unit, std::string default_toml,
                std::string meaning, std::optional<double> min = std::nullopt,
                std::optional<double> max = std::nullopt);
KeySpec Flag(std::string name, std::string default_toml, std::string meaning);
KeySpec Text(std::string name, std::string default_toml, std::string meaning,
             std::vector<std::string> choices = {});
KeySpec Reals(std::string name,
              std::string unit,
              std::string default_toml,
              std::string meaning,
              std::optional<double> min = std::nullopt,
              std::optional<double> max = std::nullopt);
KeySpec Temperature(std::string name, std::string default_toml, std::string meaning);  // K > 200
inline constexpr double kMinModulusPa = 1e6;  // smallest Young's modulus accepted [Pa]
KeySpec Modulus(std::string name, std::string default_toml, std::string meaning);  // Pa, 1e6..2e12
// Thermal properties of a solid body, bounded by engineering solids from polymers to
// diamond, with the unit slips they catch named in the message: density 500 .. 25000 kg/m^3
// (g/cm^3), conductivity 0.05 .. 2000 W/(m K) (W/(mm K)), heat capacity
// 100 .. 5000 J/(kg K) (kJ/(kg K)).
KeySpec SolidDensity(std::string name, std::string default_toml, std::string meaning);
KeySpec SolidConductivity(std::string name, std::string default_toml, std::string meaning);
KeySpec SolidHeatCapacity(std::string name, std::string default_toml, std::string meaning);
KeySpec Required(KeySpec k, std::string example);  // marks k required, with an example value

using Value = std::variant<std::monostate, bool, long long, double, std::string,
                           std::vector<double>>;

// A file read against a schema: the values given, with defaults filled for present sections
// (and for required ones), and every problem found so far. Reading never throws for content
// problems: callers add their own cross-key checks with Problem() and then call
// ThrowIfProblems(), so the user sees every problem at once. A syntax error is reported at
// its line and leaves the document empty.
class Document {
 public:
  static Document ReadFile(const Schema& schema, const std::string& path);
  static Document ReadString(const Schema& schema, const std::string& text,
                             const std::string& name);

  const std::string& path() const { return path_; }
  bool HasSection(std::string_view section) const;  // written in the file
  bool Given(std::string_view section, std::string_view key) const;   // written and valid
  bool Has(std::string_view section, std::string_view key) const;     // given or defaulted
  int Line(std::string_view section, std::string_view key) const;     // 0 if unknown

  // Typed access; a key that is neither given nor defaulted returns the zero value. Call
  // only for keys of the declared kind (an internal error otherwise).
  double Real(std::string_view section, std::string_view key) const;
  long long Int(std::string_view section, std::string_view key) const;
  bool Bool(std::string_view section, std::string_view key) const;
  std::string String(std::string_view section, std::string_view key) const;
  std::vector<double> Reals(std::string_view section, std::string_view key) const;

  // Records a cross-key problem at the key's line (or the section's, when not given).
  void Problem(std::string_view section, std::string_view key, std::string rule,
               std::string allowed);
  const std::vector<InputProblem>& problems() const { return problems_.problems(); }
  void ThrowIfProblems() const { problems_.ThrowIfAny(); }

  // The document as run: every present section with all its keys, defaults filled.
  std::string ToToml() const;
  // Text written for a value in messages: strings quoted, numbers shortest round-trip.
  std::string Show(std::string_view section, std::string_view key) const;

 private:
  struct Entry {
    Value value;
    int line = 0;
    bool given = false;
  };
  static std::string FullKey(std::string_view section, std::string_view key);
  const Entry* Get(std::string_view section, std::string_view key) const;

  const Schema* schema_ = nullptr;
  std::string path_;
  std::map<std::string, int> section_lines_;    // sections written in the file -> line
  std::map<std::string, Entry> entries_;        // "section.key" -> entry
  ProblemList problems_;

  friend class DocumentReader;
};

// How a key is described in messages and in `--print-default`.
std::string KindName(ValueKind k);                // "a number", "a string", ...
std::string UnitSuffix(const std::string& unit);  // " [m]", or "" without a unit
std::string RangeText(const KeySpec& k);          // ">= 0 and < 1", or ""
std::string AllowedText(const KeySpec& k);        // choices, or kind, range and unit

// The name of `known` within two edits of `name` (a misspelt key), closest first; "" when
// none is that close or `name` has fewer than 4 characters.
std::string NearestName(const std::string& name, const std::vector<std::string>& known);
std::string FormatValue(const Value& v);

}  // namespace tehl::internal
