#include "scene/case_inputs.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/case_reader.hpp"

namespace tehl::internal {
namespace {

void AppendFile(const std::string& path, std::string* out) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  *out += path + "\n" + (in ? text.str() : std::string("(unreadable)")) + "\n";
}

}  // namespace

std::string ReferencedInputsText(const Document& doc) {
  std::string out;
  if (doc.Has("lubricant", "name")) {
    const std::string lube = ResolveLubricantPath(doc.String("lubricant", "name"), doc.path());
    if (!lube.empty()) AppendFile(lube, &out);
  }
  for (const char* section : {"surfaces.surface1", "surfaces.surface2"}) {
    if (!doc.HasSection(section) || doc.String(section, "roughness") != "profile") continue;
    std::filesystem::path file(doc.String(section, "profile_file"));
    if (file.empty()) continue;
    if (file.is_relative()) file = std::filesystem::path(doc.path()).parent_path() / file;
    AppendFile(file.string(), &out);
  }
  return out;
}

std::string CaseWithInputsText(const std::string& case_path) {
  std::ifstream in(case_path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  std::string out = text.str();
  const Document doc = ReadCaseDocument(case_path);
  if (doc.problems().empty()) out += "\n" + ReferencedInputsText(doc);
  return out;
}

}  // namespace tehl::internal
