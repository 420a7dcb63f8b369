// The seed 004 mesh cycle with [effects] dynamic_load = true at reduced resolution
// (mesh_cycle_runs.hpp: 257 nodes, 40 steps): cases/seed004_sae40_dynamic.toml (1000 rpm)
// and cases/seed004_sae40_dynamic_resonance.toml (7500 rpm, mesh frequency 0.95 f_n) run to
// the end of the path, and near resonance the tracked pair's dynamic load differs from the
// static load sharing.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "regression/mesh_cycle_runs.hpp"
#include "scene/case_reader.hpp"
#include "scene/dynamic_load.hpp"
#include "scene/gear_case.hpp"

namespace tehl {
namespace {

using testing::Reduced;
using testing::ReducedCase;
using testing::RunReduced;

internal::GearCase ReadGear(const std::string& path) {
  internal::Document doc = internal::ReadCaseDocument(path);
  std::optional<internal::GearCase> c = internal::ReadGearCase(doc);
  doc.ThrowIfProblems();
  return *c;
}

// Largest |w_dynamic / w_static - 1| over the cycle rows of a case (GearCaseCycle).
double LargestRelativeChange(const std::string& case_name) {
  const internal::GearCase dyn = ReadGear(ReducedCase(case_name, Reduced()));
  const internal::GearCase stat =
      ReadGear(ReducedCase(case_name, Reduced({{"dynamic_load", "false"}})));
  const auto rd = internal::GearCaseCycle(dyn, 201);
  const auto rs = internal::GearCaseCycle(stat, 201);
  double largest = 0;
  for (size_t i = 0; i < rd.size(); ++i)
    largest = std::max(largest, std::abs(rd[i].load_n_per_m / rs[i].load_n_per_m - 1));
  return largest;
}

TEST(MeshCycleDynamic, Seed004At1000RpmAndNearResonanceConverge) {
  for (const char* name : {"seed004_sae40_dynamic", "seed004_sae40_dynamic_resonance"}) {
    const MeshCycleResult r = RunReduced(name);
    EXPECT_TRUE(r.converged()) << name;
    EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
    for (const MeshCycleStep& s : r.steps) {
      EXPECT_GT(s.load_n_per_m, 0.0) << name;
      EXPECT_GT(s.h_min_m, 0.0) << name;
    }
  }
}

TEST(MeshCycleDynamic, NearResonanceTheLoadDiffersFromTheStaticShare) {
  // At 0.95 f_n the dynamic load factor is about 2 (docs/dynamics.md): the pair's w departs
  // from the static share by far more than 20 % somewhere along the path.
  EXPECT_GT(LargestRelativeChange("seed004_sae40_dynamic_resonance"), 0.2);
}

TEST(MeshCycleDynamic, TheFilmRunsWithTheDynamicLoad) {
  // The mesh cycle's w(s) must be the dynamic one: compare the run's steps with the static
  // run of the same case.
  const MeshCycleResult dyn = RunReduced("seed004_sae40_dynamic_resonance");
  const MeshCycleResult stat =
      RunReduced("seed004_sae40_dynamic_resonance", Reduced({{"dynamic_load", "false"}}));
  ASSERT_EQ(dyn.steps.size(), stat.steps.size());
  double largest = 0;
  for (size_t i = 0; i < dyn.steps.size(); ++i)
    largest =
        std::max(largest, std::abs(dyn.steps[i].load_n_per_m / stat.steps[i].load_n_per_m - 1));
  EXPECT_GT(largest, 0.2);
}

}  // namespace
}  // namespace tehl
