// docs/case_format.md documents every key of the case and lubricant schemas, and its
// generated listings are exactly what `tehl case --print-default` and
// `tehl lubricant --print-default` print (so the page cannot go stale).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "base/schema.hpp"
#include "lubricant/lubricant_schema.hpp"
#include "tehl/scene/case_schema.hpp"

namespace tehl {
namespace {

std::string Doc() {
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/docs/case_format.md");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The fenced block between "<!-- begin NAME -->" and "<!-- end NAME -->".
std::string Block(const std::string& doc, const std::string& name) {
  const std::string begin = "<!-- begin " + name + " -->\n```toml\n";
  const std::string end = "```\n<!-- end " + name + " -->";
  const auto b = doc.find(begin);
  if (b == std::string::npos) return "(no begin marker)";
  const auto e = doc.find(end, b);
  if (e == std::string::npos) return "(no end marker)";
  return doc.substr(b + begin.size(), e - b - begin.size());
}

// Every section header and every key line of a schema appear in the text.
void ExpectEveryKey(const internal::Schema& schema, const std::string& text) {
  for (const auto& sec : schema.sections) {
    if (!sec.name.empty()) {
      EXPECT_NE(text.find("[" + sec.name + "]"), std::string::npos) << "[" << sec.name << "]";
    }
    for (const auto& k : sec.keys) {
      const bool listed = text.find("\n" + k.name + " = ") != std::string::npos ||
                          text.find("\n# " + k.name + " =") != std::string::npos;
      EXPECT_TRUE(listed) << schema.kind << " key " << sec.name << (sec.name.empty() ? "" : ".")
                          << k.name << " is not in docs/case_format.md";
    }
  }
}

TEST(CaseFormatDoc, ContainsEveryKeyOfTheCaseSchema) { ExpectEveryKey(CaseSchema(), Doc()); }

TEST(CaseFormatDoc, ContainsEveryKeyOfTheLubricantSchema) {
  ExpectEveryKey(internal::LubricantSchema(), Doc());
}

TEST(CaseFormatDoc, CaseListingIsTheOutputOfPrintDefault) {
  EXPECT_EQ(Block(Doc(), "case-defaults"), CaseDefaultsText())
      << "docs/case_format.md is stale: paste the output of `tehl case --print-default` "
         "between <!-- begin case-defaults --> and <!-- end case-defaults -->";
}

TEST(CaseFormatDoc, LubricantListingIsTheOutputOfPrintDefault) {
  EXPECT_EQ(Block(Doc(), "lubricant-defaults"), internal::LubricantSchema().PrintDefaults())
      << "docs/case_format.md is stale: paste the output of `tehl lubricant --print-default` "
         "between <!-- begin lubricant-defaults --> and <!-- end lubricant-defaults -->";
}

TEST(CaseFormatDoc, ShowsTheShippedSae40FileVerbatim) {
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/lubricants/sae40.toml");
  std::ostringstream s;
  s << in.rdbuf();
  EXPECT_NE(Doc().find("```toml\n" + s.str() + "```\n"), std::string::npos)
      << "the example in docs/case_format.md differs from lubricants/sae40.toml";
}

}  // namespace
}  // namespace tehl
