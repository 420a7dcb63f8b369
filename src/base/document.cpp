// Document: an input file read against its Schema (the checking itself: document_reader.cpp),
// its checked values by section and key, further problems at their lines, and the file as run.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/schema.hpp"

namespace tehl::internal {

Document Document::ReadFile(const Schema& schema, const std::string& path) {
  // Only regular files, and only up to kMaxInputFileBytes: a device such as /dev/zero or a
  // FIFO would be read without end.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  const bool folder = std::filesystem::is_directory(status);
  const bool regular = std::filesystem::is_regular_file(status);
  const auto bytes = regular ? std::filesystem::file_size(path, ec) : 0;
  std::ifstream in;
  if (regular && !ec && bytes <= kMaxInputFileBytes) in.open(path, std::ios::binary);
  if (!in.is_open() || !in) {
    Document doc;
    doc.schema_ = &schema;
    doc.path_ = path;
    std::string what = "cannot open the " + schema.kind + " file";
    if (folder)
      what = "is a folder, not a " + schema.kind + " file";
    else if (std::filesystem::exists(status) && !regular)
      what = "is not a regular file (a device, FIFO or socket), not a " + schema.kind + " file";
    else if (regular && bytes > kMaxInputFileBytes)
      what = "is " + std::to_string(bytes) + " bytes long, more than any " + schema.kind +
             " file (" + std::to_string(kMaxInputFileBytes) + ")";
    doc.problems_.Add({path, 0, "(file)", "", what, "an existing, readable file"});
    return doc;
  }
  std::ostringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  if (s.find('\0') != std::string::npos) {
    Document doc;
    doc.schema_ = &schema;
    doc.path_ = path;
    const auto line = 1 + std::count(s.begin(), s.begin() + s.find('\0'), '\n');
    doc.problems_.Add({path, static_cast<int>(line), "(file)", "",
                       "contains a NUL byte: binary data, not a text file", "a TOML text file"});
    return doc;
  }
  return ReadString(schema, s, path);
}

std::string Document::FullKey(std::string_view section, std::string_view key) {
  if (section.empty()) return std::string(key);
  return std::string(section) + "." + std::string(key);
}

const Document::Entry* Document::Get(std::string_view section, std::string_view key) const {
  const auto it = entries_.find(FullKey(section, key));
  return it == entries_.end() ? nullptr : &it->second;
}

bool Document::HasSection(std::string_view section) const {
  return section_lines_.count(std::string(section)) > 0;
}
bool Document::Given(std::string_view s, std::string_view k) const {
  const Entry* e = Get(s, k);
  return e && e->given;
}
bool Document::Has(std::string_view s, std::string_view k) const { return Get(s, k) != nullptr; }
int Document::Line(std::string_view s, std::string_view k) const {
  if (const Entry* e = Get(s, k); e && e->line > 0) return e->line;
  const auto it = section_lines_.find(std::string(s));
  return it == section_lines_.end() ? 0 : it->second;
}

double Document::Real(std::string_view s, std::string_view k) const {
  const Entry* e = Get(s, k);
  if (!e) return 0.0;
  TEHL_ASSERT(std::holds_alternative<double>(e->value), "key is not a real");
  const double* d = std::get_if<double>(&e->value);
  return d ? *d : 0.0;
}
long long Document::Int(std::string_view s, std::string_view k) const {
  const Entry* e = Get(s, k);
  const long long* i = e ? std::get_if<long long>(&e->value) : nullptr;
  return i ? *i : 0;
}
bool Document::Bool(std::string_view s, std::string_view k) const {
  const Entry* e = Get(s, k);
  const bool* b = e ? std::get_if<bool>(&e->value) : nullptr;
  return b ? *b : false;
}
std::string Document::String(std::string_view s, std::string_view k) const {
  const Entry* e = Get(s, k);
  const std::string* v = e ? std::get_if<std::string>(&e->value) : nullptr;
  return v ? *v : std::string();
}
std::vector<double> Document::Reals(std::string_view s, std::string_view k) const {
  const Entry* e = Get(s, k);
  const auto* v = e ? std::get_if<std::vector<double>>(&e->value) : nullptr;
  return v ? *v : std::vector<double>();
}

std::string Document::Show(std::string_view s, std::string_view k) const {
  const Entry* e = Get(s, k);
  return e ? FormatValue(e->value) : std::string();
}

void Document::Problem(std::string_view section,
                       std::string_view key,
                       std::string rule,
                       std::string allowed) {
  const std::string shown =
      key.empty() ? std::string("[").append(section).append("]") : FullKey(section, key);
  problems_.Add({path_, Line(section, key), shown, key.empty() ? "" : Show(section, key),
                 std::move(rule), std::move(allowed)});
}

std::string Document::ToToml() const {
  std::ostringstream o;
  o << "# " << (schema_ ? schema_->kind : "input") << " as run, defaults filled: " << path_ << "\n";
  if (!schema_) return o.str();
  for (const auto& sec : schema_->sections) {
    bool any = false;
    for (const auto& k : sec.keys) any = any || Get(sec.name, k.name);
    if (!sec.name.empty() && !HasSection(sec.name) && !sec.required && !any) continue;
    if (!sec.name.empty()) o << "\n[" << sec.name << "]\n";
    for (const auto& k : sec.keys) {
      const Entry* e = Get(sec.name, k.name);
      if (!e) continue;
      o << k.name << " = " << FormatValue(e->value);
      if (!k.unit.empty() && k.unit != "-") o << "  # [" << k.unit << "]";
      o << "\n";
    }
  }
  return o.str();
}

}  // namespace tehl::internal
