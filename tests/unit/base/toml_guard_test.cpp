// The text checks made before the TOML parser sees an input file.
#include "base/toml_guard.hpp"

#include <gtest/gtest.h>

#include "base/schema.hpp"

namespace tehl::internal {
namespace {

// Well-formed and ill-formed sequences from RFC 3629 §3 and the Unicode standard, table 3-7.
TEST(TomlGuard, AcceptsEveryWellFormedUtf8Length) {
  EXPECT_EQ(FindInvalidUtf8("a = 'x'\n").line, 0);
  EXPECT_EQ(FindInvalidUtf8("a = '\xC2\xB5m'\n").line, 0);             // U+00B5, 2 bytes
  EXPECT_EQ(FindInvalidUtf8("# \xE0\xB8\x81\xE0\xB8\xB2\n").line, 0);  // Thai, 3 bytes
  EXPECT_EQ(FindInvalidUtf8("a = '\xED\x9F\xBF'\n").line, 0);          // U+D7FF
  EXPECT_EQ(FindInvalidUtf8("a = \"\xF0\x9F\x98\x80\"\n").line, 0);    // U+1F600, 4 bytes
  EXPECT_EQ(FindInvalidUtf8("a = \"\xF4\x8F\xBF\xBF\"\n").line, 0);    // U+10FFFF
}

TEST(TomlGuard, FindsTheLineAndColumnOfIllFormedUtf8) {
  struct Case {
    const char* text;
    int line;
    const char* what;
  };
  const Case cases[] = {
      {"a = 1\nb = 'th\x9b'\n", 2, "byte 0x9b at column 8"},         // lone continuation
      {"a = '\xC0\xAF'\n", 1, "byte 0xc0 at column 6"},              // overlong '/'
      {"x\n\ny\na = '\xE0\x80\xAF'\n", 4, "byte 0xe0 at column 6"},  // overlong, 3 bytes
      {"a = '\xED\xA0\x80'\n", 1, "byte 0xed at column 6"},          // surrogate U+D800
      {"a = '\xF4\x90\x80\x80'\n", 1, "byte 0xf4 at column 6"},      // above U+10FFFF
      {"a = '\xF8\xF8\xF8'\n", 1, "byte 0xf8 at column 6"},          // no such lead byte
      {"# ok\na = '\xE2\x82'", 2, "byte 0xe2 at column 6"},          // cut short at the end
      {"a = '\xE2\x82x'\n", 1, "byte 0xe2 at column 6"},             // bad continuation
  };
  for (const Case& c : cases) {
    const TomlTextProblem p = FindInvalidUtf8(c.text);
    EXPECT_EQ(p.line, c.line) << c.what;
    EXPECT_EQ(p.what.rfind(c.what, 0), 0u) << p.what;
  }
}

// Each string form of TOML holding a byte that is not UTF-8: toml11 3.7.1 reads outside the
// string on this path (its error handling rewinds a copy of the string to a position in the
// file), so the Document must report it before parsing. Under AddressSanitizer this test
// crashes if the check is skipped.
TEST(TomlGuard, DocumentReportsNonUtf8InEveryStringFormWithoutParsingIt) {
  Schema s;
  s.kind = "test";
  s.sections = {{"body", "a body", false, {Text("name", "\"\"", "a name")}}};
  const char* texts[] = {
      "[body]\nname = 'a\x9b'\n",     "[body]\nname = \"a\x9b\"\n",
      "[body]\nname = '''a\x9b'''\n", "[body]\nname = \"\"\"a\x9b\"\"\"\n",
      "[body]\n'na\x9bme' = 'a'\n",   "[body]\n# a \x9b comment\nname = 'a'\n",
  };
  for (const char* t : texts) {
    const Document d = Document::ReadString(s, t, "bad.toml");
    ASSERT_EQ(d.problems().size(), 1u) << t;
    EXPECT_EQ(d.problems()[0].key, "(syntax)");
    EXPECT_EQ(d.problems()[0].line, 2) << t;
    EXPECT_NE(d.problems()[0].rule.find("is not UTF-8"), std::string::npos) << d.problems()[0].rule;
  }
}

TEST(TomlGuard, FindsDeepNestingAndLongDottedKeysButNotInsideStrings) {
  EXPECT_EQ(FindTooDeep("a = " + std::string(33, '[') + std::string(33, ']') + "\n").line, 1);
  EXPECT_EQ(FindTooDeep("a = " + std::string(32, '[') + std::string(32, ']') + "\n").line, 0);
  std::string key = "x";
  for (int i = 0; i < 33; ++i) key += ".x";
  EXPECT_EQ(FindTooDeep("\n" + key + " = 1\n").line, 2);
  EXPECT_EQ(FindTooDeep("a = '" + key + std::string(40, '[') + "'\n").line, 0);
}

}  // namespace
}  // namespace tehl::internal
