// Step planning of the mesh cycle: step ends on B and D exactly, the requested count, the
// minimum per segment (roughness), the automatic count's clamp, and the roughness bound as an
// input error naming [numerics] steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "tehl/error.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"
#include "support/scratch_path.hpp"

namespace tehl {
namespace {

// The seed 004 path (VALIDATION.md section 5): A..E = 6.486 / 11.046 / 11.971 / 12.390 /
// 16.950 mm from T1, so from A: B = 4.560, D = 5.904, E = g = 10.464 mm.
constexpr double kG = 10.464e-3, kB = 4.560e-3, kD = 5.904e-3;

TEST(MeshCycleSteps, LandExactlyOnBAndDWithTheRequestedCount) {
  for (int n : {3, 7, 40, 150, 201}) {
    const std::vector<double> s = MeshCycleStepPositions(kG, kB, kD, n);
    ASSERT_EQ(static_cast<int>(s.size()), n + 1) << n;
    EXPECT_EQ(s.front(), 0.0);
    EXPECT_EQ(s.back(), kG);
    EXPECT_NE(std::find(s.begin(), s.end(), kB), s.end()) << n;  // bitwise: B itself
    EXPECT_NE(std::find(s.begin(), s.end(), kD), s.end()) << n;
    for (size_t k = 1; k < s.size(); ++k) EXPECT_GT(s[k], s[k - 1]) << n;
  }
}

TEST(MeshCycleSteps, StepsAreUniformWithinSegmentsAndProportionalToLength) {
  const std::vector<double> s = MeshCycleStepPositions(kG, kB, kD, 100);
  // Largest remainder of 100 x (4.560, 1.344, 4.560) / 10.464 = 43.58, 12.84, 43.58 -> 44, 13,
  // 43 (ties broken by the later segment) or 43/13/44: each within one of the exact share.
  const auto count = [&](double a, double b) {
    return std::count_if(s.begin() + 1, s.end(), [&](double q) { return q > a && q <= b; });
  };
  EXPECT_NEAR(count(0, kB), 43.58, 1.0);
  EXPECT_NEAR(count(kB, kD), 12.84, 1.0);
  EXPECT_NEAR(count(kD, kG), 43.58, 1.0);
  const double ds = s[2] - s[1];
  for (size_t k = 1; k < s.size() && s[k] <= kB; ++k) EXPECT_NEAR(s[k] - s[k - 1], ds, 1e-15);
}

TEST(MeshCycleSteps, MinimumPerSegmentRaisesTheCount) {
  const std::vector<double> s = MeshCycleStepPositions(kG, kB, kD, 10, {5, 30, 5});
  const auto in_bd = std::count_if(s.begin(), s.end(), [](double q) { return q > kB && q <= kD; });
  EXPECT_EQ(in_bd, 30);
  EXPECT_GE(static_cast<int>(s.size()) - 1, 40);
}

TEST(MeshCycleSteps, SwitchPointsOutsideThePathAreSkipped) {
  // A switch point at A or E (as when eps_alpha is exactly 1 or 2) starts no segment.
  const std::vector<double> s = MeshCycleStepPositions(kG, 0.0, kG, 8);
  ASSERT_EQ(s.size(), 9u);
  EXPECT_NEAR(s[1], kG / 8, 1e-18);
}

TEST(MeshCycleSteps, ALoadedPartOfThePathIsSteppedLikeTheWholePath) {
  // Tip relief: the films are solved on A'..E' = [0.7, 9.8] mm; B and D stay step ends and
  // the steps are shared by the lengths inside it (3.86, 1.344, 3.896 mm of 9.1 mm).
  const double begin = 0.7e-3, end = 9.8e-3;
  const std::vector<double> s = MeshCycleStepPositions(kG, kB, kD, 91, {}, begin, end);
  ASSERT_EQ(s.size(), 92u);
  EXPECT_EQ(s.front(), begin);
  EXPECT_EQ(s.back(), end);
  EXPECT_NE(std::find(s.begin(), s.end(), kB), s.end());
  EXPECT_NE(std::find(s.begin(), s.end(), kD), s.end());
  const auto count = [&](double a, double b) {
    return std::count_if(s.begin() + 1, s.end(), [&](double q) { return q > a && q <= b; });
  };
  EXPECT_NEAR(count(begin, kB), 91 * 3.86 / 9.1, 1.0);
  EXPECT_NEAR(count(kD, end), 91 * 3.896 / 9.1, 1.0);
  // A loaded part that starts after B has no step at B.
  const std::vector<double> late = MeshCycleStepPositions(kG, kB, kD, 20, {}, 5e-3, kG);
  EXPECT_EQ(late.front(), 5e-3);
  EXPECT_EQ(std::find(late.begin(), late.end(), kB), late.end());
  EXPECT_NE(std::find(late.begin(), late.end(), kD), late.end());
}

TEST(MeshCycleSteps, AutomaticCountIsFourPerTransitClampedTo100To200) {
  EXPECT_EQ(AutomaticMeshCycleSteps(10.0), 100);
  EXPECT_EQ(AutomaticMeshCycleSteps(37.4), 150);  // ceil(149.6)
  EXPECT_EQ(AutomaticMeshCycleSteps(80.0), 200);
}

TEST(MeshCycleSteps, TooFewStepsForMovingRoughnessIsAnInputError) {
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/cases/seed004_sae40_rough.toml");
  std::ostringstream text;
  text << in.rdbuf();
  std::string t = text.str();
  t.replace(t.find("[numerics]\n"), 11, "[numerics]\nsteps = 20\n");
  const std::string path = testing::ScratchPath("tehl", "rough_steps.toml");
  std::ofstream(path) << t;
  MeshCycleRunOptions o;
  o.quiet = true;
  o.write_files = false;
  try {
    RunMeshCycle(path, o);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("numerics.steps"), std::string::npos) << m;
    EXPECT_NE(m.find("= 20"), std::string::npos) << m;
    EXPECT_NE(m.find("dt <= dx/um"), std::string::npos) << m;
    EXPECT_NE(m.find(path), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace tehl
