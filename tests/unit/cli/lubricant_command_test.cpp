// tehl lubricant: the property table, the CSV and the rejection of bad ranges (exit 2).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {
using testing::RunTehl;

std::vector<std::vector<double>> CsvRows(const std::string& text, std::string* header) {
  std::istringstream in(text);
  std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(LubricantCommand, WritesTheTableAsCsvInSiUnits) {
  const std::string csv = testing::UniqueTempPath("sae40_table.csv");
  const testing::RunResult r =
      RunTehl("lubricant sae40 --p 0:1e9:3 --T 313.15:333.15:2 --csv '" + csv + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("SAE 40"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("roelands_gamma"), std::string::npos) << r.out;
  std::string header;
  const auto rows = CsvRows(testing::ReadAll(csv), &header);
  std::remove(csv.c_str());
  EXPECT_EQ(header, "p_pa,T_k,eta_pa_s,rho_kg_m3,k_w_mk,dln_eta_dp_per_pa,nu_m2_s");
  ASSERT_EQ(rows.size(), 6u);  // 2 temperatures x 3 pressures
  // Row 0: p = 0, T = T0 -> the Table 2 inlet values of seed 004 (VALIDATION.md section 5).
  EXPECT_EQ(rows[0][0], 0.0);
  EXPECT_EQ(rows[0][1], 313.15);
  EXPECT_DOUBLE_EQ(rows[0][2], 0.1140574);
  EXPECT_DOUBLE_EQ(rows[0][3], 879.625);
  EXPECT_DOUBLE_EQ(rows[0][4], 0.125);
  // Row 1: p = 0.5 GPa. Row 3: p = 0, T = 333.15 K: eta0 exp(-0.046 * 20) (gamma form).
  EXPECT_EQ(rows[1][0], 5e8);
  EXPECT_NEAR(rows[3][2] / 0.1140574, 0.39851904, 1e-8);
  // The kinematic viscosity of the data sheets: nu = eta / rho, 0.1140574 / 879.625 =
  // 1.29666e-4 m^2/s (129.7 cSt at 40 C).
  EXPECT_NEAR(rows[0][6], 0.1140574 / 879.625, 1e-15);
}

TEST(LubricantCommand, BadRangesExitWithCodeTwoAndNameTheOption) {
  const struct {
    const char* args;
    const char* expect;
  } cases[] = {
      {"lubricant sae40 --p 0:1e9", "--p = \"0:1e9\""},
      {"lubricant sae40 --p -1e6:1e9:3", "--p = \"-1e6:1e9:3\""},
      {"lubricant sae40 --p 0:1e9:2.5", "count must be an integer"},
      {"lubricant sae40 --p 0:1e9:0", "count must be an integer"},
      {"lubricant sae40 --p a:b:c", "--p = \"a:b:c\""},
      {"lubricant sae40 --T 40:80:3", "did you give degrees Celsius?"},
      {"lubricant sae40 --T 313:393:1", "start = stop"},
      {"lubricant no_such_oil", "no such lubricant file"},
      {"lubricant", "no lubricant given"},
  };
  for (const auto& c : cases) {
    const testing::RunResult r = RunTehl(c.args);
    ASSERT_TRUE(r.exited) << c.args;
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
  }
}

TEST(LubricantCommand, PrintDefaultListsEveryLubricantSection) {
  const testing::RunResult r = RunTehl("lubricant --print-default");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* s : {"[density]", "[viscosity]", "[thermal]", "[eyring]", "source"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}

// The alpha under the table is named by the law it comes from: Houpert's for the Roelands
// laws, the file's own for Barus, none for a constant viscosity (docs/case_format.md,
// "Lubricant files").
TEST(LubricantCommand, NamesWhereThePressureViscosityCoefficientComesFrom) {
  // Houpert (VALIDATION.md section 1) with Table 2 of seed 004 (VALIDATION.md section 5):
  // 0.62 (ln 0.1140574 + 9.67) / 1.96e8 = 23.721 1/GPa.
  const testing::RunResult sae40 = RunTehl("lubricant sae40 --p 0 --T 313.15");
  ASSERT_TRUE(sae40.exited);
  ASSERT_EQ(sae40.exit_code, 0) << sae40.err;
  EXPECT_NE(sae40.out.find("Houpert pressure-viscosity coefficient alpha = Z (ln eta0 + 9.67) / "
                           "1.96e8 Pa = 23.721 1/GPa (at T0 = 313.15 K)"),
            std::string::npos)
      << sae40.out;

  namespace fs = std::filesystem;
  const fs::path dir = testing::UniqueTempPath("alpha_laws");
  fs::create_directories(dir);
  const std::string head =
      "name = \"oil\"\nsource = \"a test\"\nreference_temperature_k = 313.15\n"
      "[density]\nmodel = \"constant\"\ndensity_kg_m3 = 880.0\n"
      "[thermal]\nconductivity_model = \"constant\"\nconductivity_w_mk = 0.13\n"
      "heat_capacity_j_kgk = 1900.0\n";
  std::ofstream(dir / "barus.toml")
      << head
      << "[viscosity]\nmodel = \"barus\"\nviscosity_pa_s = 0.1\n"
         "pressure_coefficient_per_pa = 2.2e-8\ntemperature_coefficient_per_k = 0.03\n";
  std::ofstream(dir / "constant.toml")
      << head << "[viscosity]\nmodel = \"constant\"\nviscosity_pa_s = 0.1\n";
  // Barus: the file's alpha, 2.2e-8 1/Pa = 22 1/GPa; not Houpert's.
  const testing::RunResult barus =
      RunTehl("lubricant '" + (dir / "barus.toml").string() + "' --p 0 --T 313.15");
  ASSERT_EQ(barus.exit_code, 0) << barus.err;
  EXPECT_NE(barus.out.find("Barus pressure-viscosity coefficient alpha = 22 1/GPa"),
            std::string::npos)
      << barus.out;
  EXPECT_EQ(barus.out.find("Houpert"), std::string::npos) << barus.out;
  const testing::RunResult constant =
      RunTehl("lubricant '" + (dir / "constant.toml").string() + "' --p 0 --T 313.15");
  ASSERT_EQ(constant.exit_code, 0) << constant.err;
  EXPECT_NE(constant.out.find("alpha = 0 1/GPa (constant viscosity)"), std::string::npos)
      << constant.out;
  EXPECT_EQ(constant.out.find("Houpert"), std::string::npos) << constant.out;
  fs::remove_all(dir);
}

// A lubricant file beside the case is found by its name without ".toml", as the shipped
// names are; a name found nowhere lists the folders searched.
TEST(LubricantCommand, ACaseFindsItsOwnLubricantByNameAndAMissingOneListsTheFolders) {
  namespace fs = std::filesystem;
  const fs::path dir = testing::UniqueTempPath("own_oil");
  fs::create_directories(dir);
  const std::string src = std::string(TEHL_SOURCE_DIR);
  fs::copy_file(src + "/lubricants/sae40.toml", dir / "vg100.toml");
  std::string text = testing::ReadAll(src + "/cases/disc_steady.toml");
  const std::string from = "name = \"sae40\"";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "name = \"vg100\"");
  std::ofstream(dir / "disc.toml") << text;
  const testing::RunResult ok = RunTehl("case --check '" + (dir / "disc.toml").string() + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  // The case by its bare file name, from its own folder (the usual way to run one).
  const fs::path was = fs::current_path();
  fs::current_path(dir);
  const testing::RunResult bare = RunTehl("case --check disc.toml");
  fs::current_path(was);
  EXPECT_EQ(bare.exit_code, 0) << bare.err;
  text.replace(text.find("vg100"), 5, "vg101");
  std::ofstream(dir / "disc.toml", std::ios::trunc) << text;
  const testing::RunResult bad = RunTehl("case --check '" + (dir / "disc.toml").string() + "'");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("no such lubricant file"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("beside the case"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("lubricants"), std::string::npos) << bad.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tehl
