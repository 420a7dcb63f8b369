// Numbers as text are the same in every locale: a process whose global C++ locale writes
// decimal commas (a library user's std::locale::global) still gets "1.5" in result files and
// reads them back; parsing is strict.
#include "base/number_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <locale>
#include <stdexcept>
#include <string>

#include "io/csv_table.hpp"

namespace tehl {
namespace {

// A numpunct with a decimal comma and a thousands dot, as de_DE (which this machine may not
// have installed).
struct CommaDecimal : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

class CommaLocale : public ::testing::Test {
 protected:
  void SetUp() override {
    previous_ = std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
  }
  void TearDown() override { std::locale::global(previous_); }
  std::locale previous_;
};

TEST_F(CommaLocale, ResultTextKeepsTheDecimalPoint) {
  EXPECT_EQ(internal::FormatReal(1234.5), "1234.5");
  EXPECT_EQ(internal::FormatReal(2.0), "2.0");
  EXPECT_EQ(internal::FormatShort(1234.5), "1.23e+03");  // as "%.3g"
  EXPECT_EQ(internal::FormatShort(0.0125), "0.0125");
  std::string cells;
  internal::AppendCsvCell(&cells, 1.5, false);
  cells += ',';
  internal::AppendCsvCell(&cells, 12.0, true);
  EXPECT_EQ(cells, "1.500000000e+00,12");  // as "%.9e" and "%.0f" in the C locale
  double x = 0;
  ASSERT_TRUE(internal::ParseReal("1.500000000e+00", &x));
  EXPECT_EQ(x, 1.5);
}

TEST(NumberText, ParsingIsStrict) {
  double x = -1;
  EXPECT_TRUE(internal::ParseReal("+2", &x));
  EXPECT_EQ(x, 2.0);
  EXPECT_TRUE(internal::ParseReal("-2.5e-3", &x));
  EXPECT_EQ(x, -2.5e-3);
  x = -1;
  for (const char* bad : {"", "+", "1.5x", " 1.5", "1,5", "+-1", "1e999", "nan", "inf"})
    EXPECT_FALSE(internal::ParseReal(bad, &x)) << bad;
  EXPECT_EQ(x, -1);  // untouched
  EXPECT_TRUE(internal::ParseReal("nan", &x, /*allow_non_finite=*/true));
  EXPECT_TRUE(std::isnan(x));
  EXPECT_THROW(internal::ParseRealOrThrow("1.5.2", "file.csv"), std::runtime_error);
}

// Every double survives FormatReal and ParseReal bit for bit (shortest round trip).
TEST(NumberText, RealsRoundTrip) {
  for (double v : {0.1, 1.0 / 3.0, 6.02214076e23, -4.9e-324, 1.7976931348623157e308}) {
    double back = 0;
    ASSERT_TRUE(internal::ParseReal(internal::FormatReal(v), &back)) << v;
    EXPECT_EQ(back, v);
  }
}

}  // namespace
}  // namespace tehl
