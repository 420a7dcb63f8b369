// Planet count rules (seed 001 section 2.3) against Examples 2.11-2.13 and hand checks.
#include "tehl/drive/planet_design.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/error.hpp"

namespace tehl {
namespace {

// Example 2.11 (Fig. 2.17): N1 = 50, N3 = 90, standard: N2 = 20, n_max = 180/asin(22/70)
// = 9.8 (at most 9), n = 140/c: 1, 2, 4, 5, 7; the largest feasible count is 7.
TEST(PlanetRules, Seed001Example211) {
  const PlanetRules r = CheckPlanetRules({50, 90, std::nullopt, 1.0});
  EXPECT_DOUBLE_EQ(r.coaxial_planet_teeth, 20.0);
  EXPECT_NEAR(r.clearance_limit, 9.8, 0.05);
  EXPECT_NEAR(r.clearance_limit, 180.0 / (std::asin(22.0 / 70.0) * 180.0 / M_PI), 1e-12);
  EXPECT_EQ(r.max_by_clearance, 9);
  EXPECT_EQ(r.equally_spaced, (std::vector<int>{1, 2, 4, 5, 7}));
  EXPECT_EQ(r.max_planets, 7);
}

// Sun 24, ring 64, planet 20: (20 + 2)/(24 + 20) = 1/2, asin = 30 deg, N < 180/30 = 6
// exactly (eq. 2.13), so at most 5 planets; the limit is 6, not 5.999999999999999.
TEST(PlanetRules, IntegerClearanceLimitIsThatInteger) {
  const PlanetRules r = CheckPlanetRules({24, 64, std::nullopt, 1.0});
  EXPECT_EQ(r.clearance_limit, 6.0);
  EXPECT_EQ(r.max_by_clearance, 5);
}

// Example 2.12 (Fig. 2.18): (N4 + 2)/(N4 + N5) = 17/39, N3 + N5 = 78: n_max = 6.97,
// n = 1, 2, 3, 6. Teeth as read in the extraction: planet 15, sun 24, ring 54.
TEST(PlanetRules, Seed001Example212) {
  const PlanetRules r = CheckPlanetRules({24, 54, 15, 1.0});
  EXPECT_TRUE(r.coaxial);
  EXPECT_NEAR(r.clearance_limit, 6.97, 0.005);
  EXPECT_EQ(r.equally_spaced, (std::vector<int>{1, 2, 3, 6}));
  EXPECT_EQ(r.max_planets, 6);
}

// Example 2.13: sun 41, planet 18 (non-standard), ring 78: equivalent planet 18.5,
// n_max = 180/asin(20.5/59.5) = 8.93, n = 119/c: 1 or 7; at most 7 planets.
TEST(PlanetRules, Seed001Example213NonStandardPlanetUsesTheCoaxialEquivalent) {
  const PlanetRules r = CheckPlanetRules({41, 78, 18, 1.0});
  EXPECT_FALSE(r.coaxial);
  EXPECT_DOUBLE_EQ(r.coaxial_planet_teeth, 18.5);
  EXPECT_NEAR(r.clearance_limit, 8.93, 0.005);
  EXPECT_EQ(r.equally_spaced, (std::vector<int>{1, 7}));
  EXPECT_EQ(r.max_planets, 7);
}

// Hand check: sun 20, ring 40 -> planet 10; sin(pi/N) > 12/30 = 0.4: pi/N > 0.41152 rad,
// N < 7.634: at most 7; 60/N integer: 1, 2, 3, 4, 5, 6. With h_a* = 0.8: 11.6/30, N < 7.98.
TEST(PlanetRules, HandCheckedSmallSet) {
  const PlanetRules r = CheckPlanetRules({20, 40, std::nullopt, 1.0});
  EXPECT_NEAR(r.clearance_limit, M_PI / std::asin(0.4), 1e-12);
  EXPECT_NEAR(r.clearance_limit, 7.634, 0.001);
  EXPECT_EQ(r.max_by_clearance, 7);
  EXPECT_EQ(r.equally_spaced, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_TRUE(r.Assembles(12));  // 60/12 = 5, though 12 planets do not clear
  EXPECT_FALSE(r.Clears(12));
  EXPECT_FALSE(r.Assembles(7));
  const PlanetRules low = CheckPlanetRules({20, 40, std::nullopt, 0.8});
  EXPECT_NEAR(low.clearance_limit, M_PI / std::asin(11.6 / 30.0), 1e-12);
}

// Tips that just touch do not clear: sun 2, ring 12 -> planet 5, (5 + 2)/(2 + 5) = 1,
// 180 deg / asin(1) = 2 exactly, so N < 2: one planet only.
TEST(PlanetRules, TouchingTipsDoNotCount) {
  const PlanetRules r = CheckPlanetRules({2, 12, std::nullopt, 1.0});
  EXPECT_DOUBLE_EQ(r.clearance_limit, 2.0);
  EXPECT_EQ(r.max_by_clearance, 1);
}

TEST(PlanetRules, RejectsARingWithoutRoomForAPlanet) {
  EXPECT_THROW(CheckPlanetRules({40, 42, std::nullopt, 1.0}), InputError);
  EXPECT_THROW(CheckPlanetRules({0, 42, std::nullopt, 1.0}), InputError);
}

// A planet far from the coaxial one does not fit between sun and ring (seed 001 eq. 2.14):
// sun 50, ring 1000 needs a planet of 475 teeth; 20 is 455 modules short. Within two modules
// (profile shift) it is accepted as non-standard: 473 and 477 pass, 472 and 478 do not.
TEST(PlanetRules, PlanetFarFromTheCoaxialOneIsRefused) {
  EXPECT_THROW(CheckPlanetRules({50, 1000, 20, 1.0}), InputError);
  EXPECT_THROW(CheckPlanetRules({50, 1000, 472, 1.0}), InputError);
  EXPECT_THROW(CheckPlanetRules({50, 1000, 478, 1.0}), InputError);
  EXPECT_FALSE(CheckPlanetRules({50, 1000, 473, 1.0}).coaxial);
  EXPECT_FALSE(CheckPlanetRules({50, 1000, 477, 1.0}).coaxial);
  try {
    CheckPlanetRules({50, 1000, 20, 1.0});
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].key, "planet_teeth");
    EXPECT_NE(e.problems()[0].rule.find("475"), std::string::npos) << e.problems()[0].rule;
  }
}

}  // namespace
}  // namespace tehl
