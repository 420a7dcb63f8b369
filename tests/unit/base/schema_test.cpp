// The input schema: every problem reported at once with file:line, key, value and rule.
#include "base/schema.hpp"

#include <gtest/gtest.h>

namespace tehl::internal {
namespace {

Schema TestSchema() {
  Schema s;
  s.kind = "test";
  s.sections = {
      {"", "top level", false, {Text("title", "\"\"", "a title")}},
      {"body", "a body", true,
       {Required(Positive("radius_m", "m", "", "radius"), "0.01"),
        Integer("teeth", "-", "20", "teeth", 3.0),
        Temperature("t0_k", "313.15", "inlet temperature"),
        Text("model", "\"barus\"", "model", {"barus", "roelands"}),
        Reals("table", "s", "[0.0, 1.0]", "times", 0.0), Flag("on", "true", "switch")}},
      {"body.sub", "a nested table", false, {Real("x", "-", "1.5", "x")}},
  };
  return s;
}

TEST(Schema, FillsDefaultsAndReadsGivenValues) {
  const Schema s = TestSchema();
  Document d = Document::ReadString(s, "[body]\nradius_m = 0.02\nteeth = 30\n", "t.toml");
  EXPECT_TRUE(d.problems().empty());
  EXPECT_DOUBLE_EQ(d.Real("body", "radius_m"), 0.02);
  EXPECT_EQ(d.Int("body", "teeth"), 30);
  EXPECT_DOUBLE_EQ(d.Real("body", "t0_k"), 313.15);
  EXPECT_EQ(d.String("body", "model"), "barus");
  EXPECT_EQ(d.Reals("body", "table").size(), 2u);
  EXPECT_TRUE(d.Bool("body", "on"));
  EXPECT_TRUE(d.Given("body", "teeth"));
  EXPECT_FALSE(d.Given("body", "t0_k"));
  EXPECT_EQ(d.Line("body", "teeth"), 3);
}

TEST(Schema, ReportsEveryProblemWithFileLineKeyAndValue) {
  const Schema s = TestSchema();
  const std::string text =
      "[body]\n"             // 1
      "radius_m = -1.0\n"    // 2: out of range
      "teeth = 2.5\n"        // 3: wrong type
      "t0_k = 40\n"          // 4: plainly Celsius
      "model = \"roelands2\"\n"  // 5: unknown choice
      "radus = 3\n"          // 6: unknown key
      "[body.sub]\n"         // 7
      "x = \"a\"\n"          // 8: wrong type
      "[other]\n";           // 9: unknown section
  Document d = Document::ReadString(s, text, "bad.toml");
  std::vector<std::string> got;
  for (const auto& p : d.problems()) got.push_back(p.ToString());
  ASSERT_EQ(got.size(), 7u) << ::testing::PrintToString(got);
  EXPECT_NE(got[0].find("bad.toml:2: body.radius_m = -1.0: out of range: must be > 0.0 [m]"),
            std::string::npos) << got[0];
  EXPECT_NE(got[1].find("bad.toml:3: body.teeth = 2.5"), std::string::npos) << got[1];
  EXPECT_NE(got[2].find("bad.toml:4: body.t0_k = 40"), std::string::npos) << got[2];
  EXPECT_NE(got[2].find("Celsius"), std::string::npos) << got[2];
  EXPECT_NE(got[3].find("bad.toml:5: body.model = \"roelands2\": unknown value (allowed: one of "
                        "\"barus\", \"roelands\")"), std::string::npos) << got[3];
  EXPECT_NE(got[4].find("bad.toml:6: body.radus = 3: unknown key"), std::string::npos) << got[4];
  EXPECT_NE(got[5].find("bad.toml:8: body.sub.x"), std::string::npos) << got[5];
  EXPECT_NE(got[6].find("[other]: unknown section"), std::string::npos) << got[6];
  EXPECT_THROW(d.ThrowIfProblems(), InputError);
}

TEST(Schema, AMisspeltSectionIsGivenItsNearestName) {
  // "[bodi]" is one letter from the schema's [body]; "[other]" is near nothing.
  const Schema s = TestSchema();
  Document d = Document::ReadString(s, "[body]\nradius_m = 1.0\n[bodi]\n[other]\n", "m.toml");
  std::vector<std::string> got;
  for (const auto& p : d.problems()) got.push_back(p.ToString());
  ASSERT_EQ(got.size(), 2u) << ::testing::PrintToString(got);
  EXPECT_NE(got[0].find("m.toml:3: [bodi]: unknown section (did you mean [body]?)"),
            std::string::npos)
      << got[0];
  EXPECT_EQ(got[1].find("did you mean"), std::string::npos) << got[1];
}

TEST(Schema, MissingRequiredSectionAndKeyAreReported) {
  const Schema s = TestSchema();
  Document d = Document::ReadString(s, "title = \"x\"\n", "m.toml");
  ASSERT_EQ(d.problems().size(), 2u);
  EXPECT_EQ(d.problems()[0].key, "[body]");
  EXPECT_EQ(d.problems()[1].key, "body.radius_m");
  EXPECT_NE(d.problems()[1].allowed.find("radius_m = 0.01"), std::string::npos);
}

TEST(Schema, SyntaxErrorGivesItsLine) {
  const Schema s = TestSchema();
  Document d = Document::ReadString(s, "[body]\nradius_m = 0.01\nteeth = = 3\n", "syn.toml");
  ASSERT_EQ(d.problems().size(), 1u);
  EXPECT_EQ(d.problems()[0].line, 3);
  EXPECT_EQ(d.problems()[0].file, "syn.toml");
}

TEST(Schema, DocumentAsRunReadsBackToTheSameValues) {
  const Schema s = TestSchema();
  Document d = Document::ReadString(s, "[body]\nradius_m = 0.1\n[body.sub]\nx = 2\n", "r.toml");
  Document back = Document::ReadString(s, d.ToToml(), "back.toml");
  EXPECT_TRUE(back.problems().empty()) << back.ToToml();
  EXPECT_DOUBLE_EQ(back.Real("body", "radius_m"), 0.1);
  EXPECT_DOUBLE_EQ(back.Real("body.sub", "x"), 2.0);
  EXPECT_DOUBLE_EQ(back.Real("body", "t0_k"), 313.15);
}

TEST(Schema, PrintDefaultsIsAValidDocument) {
  const Schema s = TestSchema();
  Document d = Document::ReadString(s, s.PrintDefaults(), "defaults.toml");
  EXPECT_TRUE(d.problems().empty()) << s.PrintDefaults();
}

}  // namespace
}  // namespace tehl::internal
