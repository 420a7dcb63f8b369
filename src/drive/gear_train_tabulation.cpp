// The tabulation method (gear_train_tabulation.hpp): the ratios relative to the arm come from
// the group's own meshes with the arm held and the reference gear at +1 turn, solved by the
// same linear system as the whole train.
#include "tehl/drive/gear_train_tabulation.hpp"

#include <algorithm>
#include <cstdio>
#include <set>

#include "tehl/error.hpp"

namespace tehl {
namespace {

std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.6g", x);
  return buf;
}

}  // namespace

std::vector<TabulationTable> TabulateEpicyclic(const GearTrainSpec& spec,
                                               const TrainSolution& solution) {
  std::vector<TabulationTable> tables;
  const int n = static_cast<int>(spec.members.size());
  for (int c = 0; c < n; ++c) {
    const TrainMember& arm = spec.members[c];
    if (arm.kind != MemberKind::kCarrier) continue;
    std::set<std::string> group{arm.name};
    for (const TrainMember& m : spec.members)
      if (m.carrier == arm.name) group.insert(m.name);
    if (group.size() == 1) continue;
    for (const TrainMesh& mesh : spec.meshes) {
      if (mesh.kind == MeshKind::kRack) continue;
      if (group.count(mesh.a) && spec.Index(mesh.b) >= 0) group.insert(mesh.b);
      if (group.count(mesh.b) && spec.Index(mesh.a) >= 0) group.insert(mesh.a);
    }
    // The sub-train of the group: its meshes and shafts, the arm held, R at +1.
    GearTrainSpec sub;
    std::string reference, fallback_fixed, fallback_any;
    for (const TrainMember& m : spec.members) {
      if (!group.count(m.name)) continue;
      TrainMember copy = m;
      copy.speed.reset();
      if (m.name == arm.name) copy.speed = 0.0;
      if (m.kind == MemberKind::kGear) {
        if (fallback_any.empty()) fallback_any = m.name;
        if (m.carrier.empty()) {
          if (fallback_fixed.empty()) fallback_fixed = m.name;
          if (reference.empty() && m.speed) reference = m.name;
        }
      }
      sub.members.push_back(copy);
    }
    if (reference.empty()) reference = fallback_fixed.empty() ? fallback_any : fallback_fixed;
    for (TrainMember& m : sub.members)
      if (m.name == reference) m.speed = 1.0;
    for (const TrainMesh& mesh : spec.meshes)
      if (group.count(mesh.a) && group.count(mesh.b)) sub.meshes.push_back(mesh);

    TabulationTable t;
    t.carrier = arm.name;
    t.reference = reference;
    std::vector<int> cols;
    for (int j = 0; j < n; ++j)
      if (group.count(spec.members[j].name)) {
        t.columns.push_back(spec.members[j].name);
        cols.push_back(j);
      }
    std::vector<std::optional<double>> ratio(cols.size());
    try {
      const TrainSolution s = SolveGearTrain(sub);
      for (size_t k = 0; k < cols.size(); ++k) ratio[k] = s.speed[k];
    } catch (const InputError&) {
      // The group splits into parts the arm alone does not tie: leave the ratios blank.
    }
    const double w_arm = solution.speed[c];
    const double w_ref = solution.speed[spec.Index(reference)];
    // "arm fixed" for a carrier named arm, not "arm arm fixed".
    const std::string fixed = (arm.name == "arm" ? "arm" : "arm " + arm.name) + " fixed, ";
    TabulationRow r1{fixed + "+1 turn of " + reference, ratio};
    TabulationRow r2{"whole train locked to " + arm.name + ", turned " + Num(w_arm), {}};
    TabulationRow r3{fixed + reference + " turned " + Num(w_ref - w_arm), {}};
    TabulationRow r4{"absolute (sum of the two rows above)", {}};
    for (size_t k = 0; k < cols.size(); ++k) {
      r2.values.push_back(w_arm);
      // A bevel planet turns about its own axis, across the arm's: its spin relative to the
      // arm (row 3) is meaningful, a sum with the arm's speed (row 4) is not.
      const TrainMember& m = spec.members[cols[k]];
      const bool bevel_planet =
          m.carrier == arm.name &&
          std::any_of(spec.meshes.begin(), spec.meshes.end(), [&](const TrainMesh& mesh) {
            return mesh.kind == MeshKind::kBevel && (mesh.a == m.name || mesh.b == m.name);
          });
      if (ratio[k]) {
        r3.values.push_back(*ratio[k] * (w_ref - w_arm));
        r4.values.push_back(bevel_planet
                                ? std::nullopt
                                : std::optional<double>(w_arm + *ratio[k] * (w_ref - w_arm)));
      } else {
        r3.values.push_back(std::nullopt);
        r4.values.push_back(std::nullopt);
      }
    }
    t.rows = {r1, r2, r3, r4};
    tables.push_back(std::move(t));
  }
  return tables;
}

}  // namespace tehl
