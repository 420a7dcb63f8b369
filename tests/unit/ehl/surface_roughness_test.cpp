// Tests of the surface shapes and their motion (DESIGN.md section 4, surface_roughness.hpp).
#include "tehl/ehl/surface_roughness.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/units.hpp"
#include "support/scratch_path.hpp"

namespace tehl {
namespace {

std::string WriteTemp(const std::string& name, const std::string& text) {
  const std::string path = testing::ScratchPath("tehl_surface_roughness", name);
  std::ofstream(path) << text;
  return path;
}

// Runs ReadFile and returns the problems of the InputError it must throw.
std::vector<InputProblem> ReadProblems(const std::string& path) {
  try {
    MeasuredProfile::ReadFile(path);
  } catch (const InputError& e) {
    return e.problems();
  }
  ADD_FAILURE() << "no InputError for " << path;
  return {};
}

TEST(SinusoidalWaviness, MatchesTheDesignFormula) {
  // DESIGN.md section 4: A sin(2 pi (x - x0 - travel)/Lambda); here phase = -2 pi x0/Lambda.
  const double a = 0.3e-6, lambda = 80e-6, x0 = 13e-6;
  const SinusoidalWaviness s(a, lambda, -2 * kPi * x0 / lambda);
  for (double x : {-2e-4, -3.3e-5, 0.0, 1.7e-5, 2.5e-4}) {
    for (double d : {0.0, 1e-5, 3.1e-3}) {
      EXPECT_NEAR(s.Height(x, d), a * std::sin(2 * kPi * (x - x0 - d) / lambda), 1e-12 * a);
    }
  }
}

TEST(SinusoidalWaviness, MovesWithTravel) {
  // Height(x + d, d) = Height(x, 0): the feature at material point x is carried to x + d.
  const SinusoidalWaviness s(0.5e-6, 60e-6, 0.4);
  for (double x : {-1e-4, 0.0, 3.7e-5}) {
    for (double d : {2.3e-6, 4.1e-5, 1.234e-2}) {
      EXPECT_NEAR(s.Height(x + d, d), s.Height(x, 0.0), 1e-9 * 0.5e-6) << x << " " << d;
    }
  }
  EXPECT_NEAR(s.Height(0.0, 0.0), 0.5e-6 * std::sin(0.4), 1e-18);
}

TEST(SinusoidalWaviness, RejectsNonPositiveWavelength) {
  EXPECT_THROW(SinusoidalWaviness(1e-6, 0.0), InputError);
  EXPECT_THROW(SinusoidalWaviness(1e-6, -5e-5), InputError);
  EXPECT_THROW(SinusoidalWaviness(NAN, 5e-5), InputError);
  try {
    SinusoidalWaviness(1e-6, -5e-5);
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems().at(0).key, "SinusoidalWaviness::wavelength_m");
  }
}

TEST(SmoothSurface, IsFlat) {
  const SmoothSurface s;
  EXPECT_EQ(s.Height(1e-4, 3.0), 0.0);
}

TEST(SampleHeights, FillsTheArray) {
  const SinusoidalWaviness s(1e-6, 1e-4);
  const std::vector<double> x = {0.0, 2.5e-5, 5e-5};
  std::vector<double> out(3);
  SampleHeights(s, x.data(), 3, 0.0, out.data());
  for (int i = 0; i < 3; ++i) EXPECT_EQ(out[i], s.Height(x[i], 0.0));
}

TEST(MeasuredProfile, InterpolatesLinearlyAndRemovesTheMean) {
  // Points (0, 1), (1, 3), (2, 1) micrometres-ish, spacing 1: period L = 2 + 1 = 3 with a
  // closing segment from z = 1 back to z = 1. Integral over a period by trapezoids:
  // 0.5 (1 + 3) + 0.5 (3 + 1) + 1 * 1 = 5, mean 5/3 (derived by hand).
  const MeasuredProfile p({0.0, 1.0, 2.0}, {1.0, 3.0, 1.0});
  EXPECT_DOUBLE_EQ(p.period_m(), 3.0);
  EXPECT_DOUBLE_EQ(p.removed_mean_m(), 5.0 / 3.0);
  EXPECT_DOUBLE_EQ(p.Height(0.5, 0.0), 2.0 - 5.0 / 3.0);
  EXPECT_DOUBLE_EQ(p.Height(1.0, 0.0), 3.0 - 5.0 / 3.0);
  EXPECT_DOUBLE_EQ(p.Height(2.5, 0.0), 1.0 - 5.0 / 3.0);  // closing segment
  // rms of the periodic profile with the mean removed: sum over segments of
  // dx (a^2 + a b + b^2)/3 with a, b the heights minus 5/3 (derived by hand), over L = 3.
  const double lo = 1.0 - 5.0 / 3.0, hi = 3.0 - 5.0 / 3.0;
  const double ms = (2 * (lo * lo + lo * hi + hi * hi) / 3 + lo * lo) / 3.0;
  EXPECT_NEAR(p.rms_m(), std::sqrt(ms), 1e-15);
}

TEST(MeasuredProfile, IsPeriodicAndContinuousWhereCopiesJoin) {
  const MeasuredProfile p({-1e-4, 0.0, 1e-4, 2e-4}, {0.2e-6, -0.5e-6, 0.1e-6, 0.4e-6});
  const double l = p.period_m();
  EXPECT_DOUBLE_EQ(l, 4e-4);
  for (double x : {-1e-4, -3e-5, 0.0, 1.5e-4, 2.7e-4}) {
    EXPECT_NEAR(p.Height(x + l, 0.0), p.Height(x, 0.0), 1e-18);
    EXPECT_NEAR(p.Height(x - 3 * l, 0.0), p.Height(x, 0.0), 1e-18);
  }
  // Continuity at the join x_last + spacing = x_first + L.
  const double join = -1e-4 + l;
  EXPECT_NEAR(p.Height(join - 1e-12, 0.0), p.Height(join + 1e-12, 0.0), 1e-13);
}

TEST(MeasuredProfile, MovesWithTravel) {
  const MeasuredProfile p({0.0, 1e-5, 2e-5, 3e-5}, {0.0, 1e-7, -2e-7, 5e-8});
  for (double x : {-1e-5, 0.0, 1.3e-5}) {
    for (double d : {3e-6, 7.7e-5, 2e-3}) {
      EXPECT_NEAR(p.Height(x + d, d), p.Height(x, 0.0), 1e-17) << x << " " << d;
    }
  }
}

TEST(MeasuredProfile, ReadsCommentsCommasAndBlankLines) {
  const std::string path = WriteTemp("good.txt",
                                     "# x [m], height [m]\n"
                                     "0.0  1.0e-6\n"
                                     "\n"
                                     "1.0e-5, 3.0e-6   # a comment\n"
                                     "2.0e-5\t1.0e-6\n");
  const MeasuredProfile p = MeasuredProfile::ReadFile(path);
  EXPECT_EQ(p.points(), 3);
  EXPECT_NEAR(p.removed_mean_m(), 5.0e-6 / 3.0, 1e-20);  // as in the hand-derived case above
  EXPECT_NE(p.Describe().find(path), std::string::npos);
  std::filesystem::remove(path);
}

TEST(MeasuredProfile, ReaderRejectsBadFilesWithFileAndLine) {
  // Line 3: not a number; line 4: three columns; line 6: x not increasing; line 7: inf.
  const std::string path = WriteTemp("bad.txt",
                                     "# profile\n"
                                     "0.0 1e-6\n"
                                     "1e-5 abc\n"
                                     "2e-5 1e-6 3e-6\n"
                                     "3e-5 0\n"
                                     "3e-5 1e-7\n"
                                     "4e-5 inf\n");
  const std::vector<InputProblem> problems = ReadProblems(path);
  ASSERT_EQ(problems.size(), 4u);
  EXPECT_EQ(problems[0].file, path);
  EXPECT_EQ(problems[0].line, 3);
  EXPECT_EQ(problems[0].key, "height");
  EXPECT_EQ(problems[0].value, "abc");
  EXPECT_EQ(problems[1].line, 4);
  EXPECT_EQ(problems[1].key, "row");
  EXPECT_EQ(problems[2].line, 6);
  EXPECT_EQ(problems[2].key, "x");
  EXPECT_EQ(problems[2].value, "3e-5");
  EXPECT_EQ(problems[3].line, 7);
  EXPECT_EQ(problems[3].key, "height");
  // The message printed for the user carries "file:line".
  try {
    MeasuredProfile::ReadFile(path);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":6"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(MeasuredProfile, ReaderRejectsFewerThanTwoPoints) {
  const std::string path = WriteTemp("one.txt", "# only one point\n0 1e-6\n");
  const std::vector<InputProblem> problems = ReadProblems(path);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "points");
  EXPECT_EQ(problems[0].value, "1");
  EXPECT_EQ(problems[0].line, 2);
  std::filesystem::remove(path);
}

TEST(MeasuredProfile, ReaderRejectsMissingFile) {
  const std::vector<InputProblem> problems = ReadProblems("/nonexistent/profile.txt");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].file, "/nonexistent/profile.txt");
}

TEST(MeasuredProfile, ArrayConstructorAppliesTheSameRules) {
  EXPECT_THROW(MeasuredProfile({0.0, 0.0}, {1.0, 2.0}), InputError);
  EXPECT_THROW(MeasuredProfile({0.0, 1.0}, {1.0}), InputError);
  EXPECT_THROW(MeasuredProfile({0.0}, {1.0}), InputError);
}

}  // namespace
}  // namespace tehl
