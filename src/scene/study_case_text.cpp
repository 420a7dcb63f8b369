#include "scene/study_case_text.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "base/schema.hpp"
#include "scene/case_reader.hpp"
#include "tehl/scene/case_schema.hpp"

namespace tehl::internal {
namespace {
namespace fs = std::filesystem;

// A TOML string literal's text, or "" when `literal` is not a plain string literal.
std::string Unquote(const std::string& literal) {
  if (literal.size() < 2 || literal.front() != '"' || literal.back() != '"') return "";
  std::string s;
  for (size_t i = 1; i + 1 < literal.size(); ++i) {
    if (literal[i] == '\\' && i + 2 < literal.size()) ++i;
    s += literal[i];
  }
  return s;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

bool IsHeader(const std::string& line) { return !line.empty() && line[0] == '['; }

// The line written for a key: as Document::ToToml writes it, with the unit comment.
std::string KeyLine(const std::string& section, const std::string& key,
                    const std::string& literal) {
  std::string line = key + " = " + literal;
  if (const SectionSpec* s = CaseSchema().Find(section))
    if (const KeySpec* k = s->Find(key); k && !k->unit.empty() && k->unit != "-")
      line += "  # [" + k->unit + "]";
  return line;
}

}  // namespace

std::pair<std::string, std::string> SplitCaseKey(const std::string& dotted) {
  const auto dot = dotted.rfind('.');
  if (dot == std::string::npos) return {"", dotted};
  return {dotted.substr(0, dot), dotted.substr(dot + 1)};
}

std::string ApplyCaseOverrides(const std::string& case_text,
                               const std::vector<CaseOverride>& overrides) {
  std::vector<std::string> lines = Lines(case_text);
  for (const auto& o : overrides) {
    const auto [section, key] = SplitCaseKey(o.key);
    const std::string header = "[" + section + "]";
    const std::string line = KeyLine(section, key, o.literal);
    // Find the section (top-level keys: before the first header).
    size_t begin = 0;
    bool found = section.empty();
    if (!found)
      for (size_t i = 0; i < lines.size(); ++i)
        if (lines[i] == header) {
          begin = i + 1;
          found = true;
          break;
        }
    if (!found) {
      lines.push_back("");
      lines.push_back(header);
      lines.push_back(line);
      continue;
    }
    size_t end = begin;
    while (end < lines.size() && !IsHeader(lines[end])) ++end;
    bool replaced = false;
    for (size_t i = begin; i < end && !replaced; ++i)
      if (lines[i].rfind(key + " = ", 0) == 0) {
        lines[i] = line;
        replaced = true;
      }
    if (!replaced) {
      size_t at = end;  // after the section's last non-blank line
      while (at > begin && lines[at - 1].empty()) --at;
      lines.insert(lines.begin() + static_cast<long>(at), line);
    }
  }
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

std::string RemoveCaseSections(const std::string& case_text,
                               const std::vector<std::string>& sections) {
  std::string out;
  bool keep = true;
  for (const std::string& line : Lines(case_text)) {
    if (IsHeader(line)) {
      const std::string name = line.substr(1, line.find(']') - 1);
      keep = std::find(sections.begin(), sections.end(), name) == sections.end();
    }
    if (keep) out += line + "\n";
  }
  return out;
}

void AddPathOverrides(const Document& base,
                      const std::string& base_path,
                      std::vector<CaseOverride>* o) {
  auto current = [&](const std::string& key, const std::string& section, const std::string& k) {
    for (const auto& x : *o)
      if (x.key == key) return Unquote(x.literal);
    return base.String(section, k);
  };
  const std::string lub = current("lubricant.name", "lubricant", "name");
  const std::string resolved = ResolveLubricantPath(lub, base_path);
  if (!resolved.empty())
    o->push_back({"lubricant.name", FormatValue(Value(fs::absolute(resolved).string()))});
  for (const char* s : {"surfaces.surface1", "surfaces.surface2"}) {
    const std::string file = current(std::string(s) + ".profile_file", s, "profile_file");
    if (file.empty() || fs::path(file).is_absolute()) continue;
    const fs::path abs = fs::absolute(fs::path(base_path).parent_path() / file).lexically_normal();
    o->push_back({std::string(s) + ".profile_file", FormatValue(Value(abs.string()))});
  }
}

}  // namespace tehl::internal
