// The gear train as one linear system A w = b (gear_train.hpp). Kinematic rows (meshes,
// shafts) come first, then the inputs in file order, so a rank test per added row tells a
// redundant or contradictory input from the relation it repeats.
#include "tehl/drive/gear_train.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "drive/train_mesh_rows.hpp"
#include "tehl/error.hpp"

namespace tehl {
namespace {

constexpr double kRankTolerance = 1e-10;  // pivot threshold on unit-norm rows [-]
constexpr double kRestFraction = 1e-12;   // |w| below this times max |w| is rest [-]

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
    const int rows = static_cast<int>(rows_.size());
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rows, n);
    Eigen::VectorXd b(rows);
    for (int r = 0; r < rows; ++r) {
      for (auto [j, v] : rows_[r].coeffs) a(r, j) += v;
      b(r) = rows_[r].rhs;
      const double norm = a.row(r).norm();
      if (norm > 0) {
        a.row(r) /= norm;
        b(r) /= norm;
      }
    }
    // Add the rows one by one: an input row that does not raise the rank repeats what the
    // earlier rows already fix.
    int rank = 0;
    for (int r = 0; r < rows; ++r) {
      Eigen::FullPivLU<Eigen::MatrixXd> lu(a.topRows(r + 1));
      lu.setThreshold(kRankTolerance);
      const int new_rank = static_cast<int>(lu.rank());
      if (new_rank == rank && rows_[r].input) {
        const TrainMember& m = spec_.members[rows_[r].member];
        const Eigen::VectorXd w = a.topRows(r).completeOrthogonalDecomposition().solve(b.head(r));
        const double implied = w(rows_[r].member);
        const bool same = std::abs(implied - rows_[r].rhs) <= 1e-9 * (1 + std::abs(implied));
        Problem(m.where, "speed",
                std::string(same ? "over-determined: " : "contradictory: ") +
                    "the meshes, shafts and earlier inputs already fix the speed of " + m.name +
                    " at " + Num(std::abs(implied) < 1e-12 ? 0.0 : implied) +
                    (m.kind == MemberKind::kRack ? " m/s" : " rad/s") +
                    (std::abs(implied) < 1e-12 ? " (the train is locked there)" : ""),
                "a speed on a member the other relations leave free (remove this one)");
      }
      rank = new_rank;
    }
    problems_.ThrowIfAny();
    // The free motions of the meshes and shafts alone (the kinematic rows come first).
    int kinematic = 0;
    while (kinematic < rows && !rows_[kinematic].input) ++kinematic;
    Eigen::MatrixXd free_motions = Eigen::MatrixXd::Identity(n, n);
    if (kinematic > 0) {
      Eigen::FullPivLU<Eigen::MatrixXd> lu(a.topRows(kinematic));
      lu.setThreshold(kRankTolerance);
      free_motions = lu.rank() == n ? Eigen::MatrixXd::Zero(n, 0) : Eigen::MatrixXd(lu.kernel());
    }
    if (free_motions.cols() > 0) {
      Eigen::HouseholderQR<Eigen::MatrixXd> qr(free_motions);  // orthonormal basis
      free_motions = qr.householderQ() * Eigen::MatrixXd::Identity(n, free_motions.cols());
    }
    // A member no free motion moves is locked by the meshes themselves (an odd loop of
    // external gears): its rest is no answer. Locked inputs were reported above.
    std::vector<std::string> locked;
    std::string locked_where;
    for (int j = 0; j < n; ++j)
      if (free_motions.cols() == 0 || free_motions.row(j).cwiseAbs().maxCoeff() < 1e-9) {
        locked.push_back(spec_.members[j].name);
        if (locked_where.empty()) locked_where = spec_.members[j].where;
      }
    if (!locked.empty()) {
      Problem(locked_where, "speed",
              "locked: the meshes and shafts alone hold " + Join(locked) +
                  " at rest (a loop of meshes that cannot turn, such as three external gears "
                  "in a triangle)",
              "meshes that leave the train free to turn (remove the mesh that closes the "
              "loop)");
      problems_.ThrowIfAny();
    }
    if (rank < n) {
      Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
      lu.setThreshold(kRankTolerance);
      const Eigen::MatrixXd kernel = lu.kernel();
      std::vector<std::string> free;
      std::string where;
      for (int j = 0; j < n; ++j)
        if (kernel.row(j).cwiseAbs().maxCoeff() > 1e-8) {
          free.push_back(spec_.members[j].name);
          if (where.empty()) where = spec_.members[j].where;
        }
      Problem(where, "speed",
              "under-determined: the speeds of " + Join(free) + " are not fixed (" +
                  std::to_string(n - rank) + " more condition" + (n - rank > 1 ? "s" : "") +
                  " needed)",
              "a driven speed (speed_rpm, speed_rad_s) or held = true on one of them, or a "
              "mesh or shaft connecting them to the rest");
      problems_.ThrowIfAny();
    }
    Eigen::VectorXd w = a.colPivHouseholderQr().solve(b);
    // Round-off of a member at rest (a held ring's planet mesh, say) is rest.
    const double w_max = w.cwiseAbs().maxCoeff();
    for (int j = 0; j < n; ++j)
      if (std::abs(w(j)) < kRestFraction * w_max) w(j) = 0.0;
    TrainSolution s;
    s.speed.assign(w.data(), w.data() + n);
    s.equations = rows;
    s.unknowns = n;
    s.rank = rank;
    s.residual = rows ? (a * w - b).cwiseAbs().maxCoeff() / (1.0 + w.cwiseAbs().maxCoeff()) : 0;
    s.free_motions.assign(free_motions.cols(), std::vector<double>(n));
    for (int k = 0; k < free_motions.cols(); ++k)
      for (int j = 0; j < n; ++j) s.free_motions[k][j] = free_motions(j, k);
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
