// The gear train as one linear system A w = b (gear_train.hpp), solved in the speeds of the
// groups of members that two-term relations tie together (train_groups.hpp): the speeds
// are products of tooth ratios, exact whatever the ratio. Kinematic rows (meshes, shafts)
// come first, then the inputs in file order, so a rank test per added row tells a
// redundant or contradictory input from the relation it repeats.
#include "tehl/drive/gear_train.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "drive/train_groups.hpp"
#include "drive/train_mesh_rows.hpp"
#include "tehl/error.hpp"

namespace tehl {
namespace {

using Row = internal::TrainRow;

std::string Num(double x) { return internal::TrainNumber(x); }

std::string Join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

class TrainBuilder {
 public:
  explicit TrainBuilder(const GearTrainSpec& spec) : spec_(spec) {}

  void Problem(const std::string& where,
               const std::string& field,
               std::string rule,
               std::string allowed) {
    problems_.Add({"", 0, where.empty() ? field : where + "." + field, "", std::move(rule),
                   std::move(allowed)});
  }

  void CheckMembers() {
    std::map<std::string, int> seen;
    for (const TrainMember& m : spec_.members) {
      if (m.name.empty()) Problem(m.where, "name", "a member needs a name", "a non-empty name");
      if (seen[m.name]++ == 1)
        Problem(m.where, "name", "the name '" + m.name + "' is used twice",
                "one name per gear, carrier and rack");
      if (m.kind == MemberKind::kGear && m.teeth < 1)
        Problem(m.where, "teeth", "a gear needs at least one tooth (a worm one start)",
                "an integer >= 1");
      if (!m.carrier.empty()) {
        const int c = spec_.Index(m.carrier);
        if (m.kind != MemberKind::kGear)
          Problem(m.where, "carrier", "only gears ride on a carrier", "no carrier key here");
        else if (c < 0 || spec_.members[c].kind != MemberKind::kCarrier)
          Problem(m.where, "carrier", "'" + m.carrier + "' is not a carrier of this train",
                  "the name of a [carrier.NAME] section, or \"\" for the frame");
      }
      if (m.speed && !std::isfinite(*m.speed))
        Problem(m.where, "speed", "must be a finite number", "a speed [rad/s] or [m/s]");
    }
    // Gears on one shaft share their axis, hence their carrier.
    std::map<std::string, const TrainMember*> first_on_shaft;
    for (const TrainMember& m : spec_.members) {
      if (m.shaft.empty()) continue;
      if (m.kind == MemberKind::kRack)
        Problem(m.where, "shaft", "a rack slides; it has no shaft", "no shaft key for a rack");
      const auto [it, fresh] = first_on_shaft.emplace(m.shaft, &m);
      if (!fresh && it->second->carrier != m.carrier)
        Problem(m.where, "carrier",
                "shares shaft '" + m.shaft + "' with " + it->second->name +
                    " but rides on another carrier",
                "the same carrier as every member of its shaft");
    }
  }

  void AddShafts() {
    std::map<std::string, int> first;
    for (int i = 0; i < static_cast<int>(spec_.members.size()); ++i) {
      const TrainMember& m = spec_.members[i];
      if (m.shaft.empty() || m.kind == MemberKind::kRack) continue;
      const auto [it, fresh] = first.emplace(m.shaft, i);
      if (!fresh)
        rows_.push_back(
            {{{i, 1.0}, {it->second, -1.0}},
             0.0,
             false,
             -1,
             "shaft " + m.shaft + " (" + spec_.members[it->second].name + " = " + m.name + ")",
             m.where});
    }
  }

  void AddInputs() {
    for (int i = 0; i < static_cast<int>(spec_.members.size()); ++i) {
      const TrainMember& m = spec_.members[i];
      if (!m.speed || !std::isfinite(*m.speed)) continue;
      rows_.push_back({{{i, 1.0}},
                       *m.speed,
                       true,
                       i,
                       (*m.speed == 0.0 ? "held " : "input ") + m.name,
                       m.where});
    }
  }

  void CheckEnds() {
    for (auto [name, field] : {std::pair{spec_.input, "input"}, {spec_.output, "output"}})
      if (!name.empty() && spec_.Index(name) < 0)
        Problem("train", field, "no member named '" + name + "'", "a gear, carrier or rack");
    // w_a / w_a = 1 whatever the train: a slip of the file, not a train value.
    if (!spec_.input.empty() && spec_.output == spec_.input)
      Problem("train", "output",
              "the output is the input member " + spec_.input + ": w_" + spec_.input + " / w_" +
                  spec_.input + " = 1 says nothing of the train",
              "a member other than the input (" + spec_.input + ")");
  }

  TrainSolution Solve() {
    CheckMembers();
    CheckEnds();
    internal::MeshRows meshes(spec_, &rows_, &problems_);
    for (const TrainMesh& m : spec_.meshes) meshes.Add(m);
    AddShafts();
    AddInputs();
    problems_.ThrowIfAny();

    const int n = static_cast<int>(spec_.members.size());
    const internal::GroupSystem system(n, rows_);
    // Add the rows one by one: an input row that does not raise the rank repeats what the
    // earlier rows already fix.
    int rank = 0;
    for (int r = 0; r < system.rows(); ++r) {
      const int new_rank = system.Rank(r + 1);
      if (new_rank == rank && r >= system.kinematic_rows()) ReportRepeatedInput(system, r);
      rank = new_rank;
    }
    problems_.ThrowIfAny();
    const Eigen::MatrixXd free_motions = system.FreeMotions();
    CheckLocked(system, free_motions);
    const int count = system.groups().count;
    if (rank < count) ReportFree(system);
    TrainSolution s;
    s.speed = system.Speeds(system.Solve(system.rows()));
    s.equations = static_cast<int>(rows_.size());
    s.unknowns = n;
    s.rank = n - count + rank;
    s.residual = Residual(s.speed);
    for (int k = 0; k < free_motions.cols(); ++k) {
      std::vector<double> v = system.Speeds(free_motions.col(k));
      double largest = 0;
      for (double x : v) largest = std::max(largest, std::abs(x));
      for (double& x : v) x /= largest;
      s.free_motions.push_back(std::move(v));
    }
    const int in = spec_.Index(spec_.input), out = spec_.Index(spec_.output);
    if (in >= 0 && s.speed[in] == 0.0) {
      const TrainMember& m = spec_.members[in];
      Problem("train", "input",
              m.speed && *m.speed == 0.0
                  ? "the input member is held: w_output / w_input is undefined"
                  : "the input member " + m.name + " is at rest: w_output / w_input is undefined",
              "a member that turns: the driven member, or one the train turns");
      problems_.ThrowIfAny();
    }
    if (in >= 0 && out >= 0) s.train_value = s.speed[out] / s.speed[in];
    return s;
  }

 private:
  // Reduced input row r repeats the earlier rows: over-determined or contradictory.
  void ReportRepeatedInput(const internal::GroupSystem& system, int r) {
    const Row& row = rows_[system.input_row(r)];
    const TrainMember& m = spec_.members[row.member];
    const double implied = system.Speeds(system.Solve(r))[row.member];
    const bool same =
        std::abs(implied - row.rhs) <= 1e-9 * std::max(std::abs(implied), std::abs(row.rhs));
    Problem(m.where, "speed",
            std::string(same ? "over-determined: " : "contradictory: ") +
                "the meshes, shafts and earlier inputs already fix the speed of " + m.name +
                " at " + Num(implied) + (m.kind == MemberKind::kRack ? " m/s" : " rad/s") +
                (implied == 0.0 ? " (the train is locked there)" : ""),
            "a speed on a member the other relations leave free (remove this one)");
  }

  // Members of the groups no free motion moves are locked by the meshes themselves (an odd
  // loop of external gears): their rest is no answer. Locked inputs were reported above.
  void CheckLocked(const internal::GroupSystem& system, const Eigen::MatrixXd& free) {
    std::vector<std::string> locked;
    std::string where;
    for (int j = 0; j < static_cast<int>(spec_.members.size()); ++j) {
      const int g = system.groups().group[j];
      if (free.cols() > 0 && free.row(g).norm() >= 1e-9) continue;
      locked.push_back(spec_.members[j].name);
      if (where.empty()) where = spec_.members[j].where;
    }
    if (locked.empty()) return;
    Problem(where, "speed",
            "locked: the meshes and shafts alone hold " + Join(locked) +
                " at rest (a loop of meshes that cannot turn, such as three external gears "
                "in a triangle)",
            "meshes that leave the train free to turn (remove the mesh that closes the loop)");
    problems_.ThrowIfAny();
  }

  void ReportFree(const internal::GroupSystem& system) {
    const Eigen::MatrixXd kernel = system.Kernel();
    const int missing = static_cast<int>(kernel.cols());
    std::vector<std::string> free;
    std::string where;
    for (int j = 0; j < static_cast<int>(spec_.members.size()); ++j)
      if (kernel.row(system.groups().group[j]).cwiseAbs().maxCoeff() > 1e-8) {
        free.push_back(spec_.members[j].name);
        if (where.empty()) where = spec_.members[j].where;
      }
    Problem(where, "speed",
            "under-determined: the speeds of " + Join(free) + " are not fixed (" +
                std::to_string(missing) + " more condition" + (missing > 1 ? "s" : "") + " needed)",
            "a driven speed (speed_rpm, speed_rad_s) or held = true on one of them, or a "
            "mesh or shaft connecting them to the rest");
    problems_.ThrowIfAny();
  }

  // max |A w - b| over the rows of the members' system, each row at unit norm, relative to
  // the largest speed.
  double Residual(const std::vector<double>& w) const {
    double worst = 0, largest = 0;
    for (double x : w) largest = std::max(largest, std::abs(x));
    for (const Row& row : rows_) {
      double sum = -row.rhs, norm = 0;
      for (auto [j, v] : row.coeffs) {
        sum += v * w[j];
        norm += v * v;
      }
      if (norm > 0) worst = std::max(worst, std::abs(sum) / std::sqrt(norm));
    }
    return worst / (1.0 + largest);
  }

  const GearTrainSpec& spec_;
  std::vector<Row> rows_;
  ProblemList problems_;
};

}  // namespace

std::string ToString(MeshKind k) {
  switch (k) {
    case MeshKind::kExternal:
      return "external";
    case MeshKind::kInternal:
      return "internal";
    case MeshKind::kBevel:
      return "bevel";
    case MeshKind::kWorm:
      return "worm";
    case MeshKind::kRack:
      return "rack";
  }
  return "?";
}

std::optional<MeshKind> MeshKindFromString(std::string_view s) {
  for (MeshKind k : {MeshKind::kExternal, MeshKind::kInternal, MeshKind::kBevel, MeshKind::kWorm,
                     MeshKind::kRack})
    if (ToString(k) == s) return k;
  return std::nullopt;
}

std::string ToString(WormHand h) {
  return h == WormHand::kRight ? "right" : h == WormHand::kLeft ? "left" : "";
}

std::string ToString(MemberKind k) {
  return k == MemberKind::kGear ? "gear" : k == MemberKind::kCarrier ? "carrier" : "rack";
}

int GearTrainSpec::Index(std::string_view name) const {
  for (size_t i = 0; i < members.size(); ++i)
    if (members[i].name == name) return static_cast<int>(i);
  return -1;
}

TrainSolution SolveGearTrain(const GearTrainSpec& spec) { return TrainBuilder(spec).Solve(); }

TrainSolution SolveUnitInput(const GearTrainSpec& spec) {
  GearTrainSpec unit = spec;
  for (TrainMember& m : unit.members) {
    if (m.name == spec.input)
      m.speed = 1.0;
    else if (m.speed)
      m.speed = 0.0;
  }
  return SolveGearTrain(unit);
}

}  // namespace tehl
