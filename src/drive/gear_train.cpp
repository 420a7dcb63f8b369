// The gear train as one linear system A w = b (gear_train.hpp). Kinematic rows (meshes,
// shafts) come first, then the inputs in file order, so a rank test per added row tells a
// redundant or contradictory input from the relation it repeats.
#include "tehl/drive/gear_train.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "tehl/error.hpp"

namespace tehl {
namespace {

constexpr double kRankTolerance = 1e-10;  // pivot threshold on unit-norm rows [-]
constexpr double kRestFraction = 1e-12;   // |w| below this times max |w| is rest [-]

struct Row {
  std::vector<std::pair<int, double>> coeffs;
  double rhs = 0.0;
  bool input = false;
  int member = -1;    // input rows: the member
  std::string label;  // for messages
  std::string where;  // kinematic rows: the mesh or member section that gave the row
};

std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

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

  // The carrier index a mesh turns with (-1: the frame), or -2 after a problem.
  int MeshFrame(const TrainMesh& mesh, const TrainMember& a, const TrainMember& b) {
    if (!a.carrier.empty() && !b.carrier.empty() && a.carrier != b.carrier) {
      Problem(mesh.where, "b",
              a.name + " rides on " + a.carrier + " and " + b.name + " on " + b.carrier,
              "a mesh between gears of one carrier, or between a carrier's gear and a gear "
              "on a fixed axis");
      return -2;
    }
    const std::string& c = a.carrier.empty() ? b.carrier : a.carrier;
    return c.empty() ? -1 : spec_.Index(c);
  }

  void AddMesh(const TrainMesh& mesh) {
    const int ia = spec_.Index(mesh.a), ib = spec_.Index(mesh.b);
    bool ok = true;
    for (auto [i, field, name] : {std::tuple{ia, "a", mesh.a}, std::tuple{ib, "b", mesh.b}}) {
      if (i < 0) {
        Problem(mesh.where, field, "no member named '" + name + "'",
                "the name of a [gear.NAME] (or, for b of a rack mesh, [rack.NAME]) section");
        ok = false;
      }
    }
    if (!ok) return;
    if (ia == ib)
      return Problem(mesh.where, "b", "a gear cannot mesh with itself", "two different gears");
    const TrainMember& a = spec_.members[ia];
    const TrainMember& b = spec_.members[ib];
    const std::string what = mesh.a + "-" + mesh.b;
    if (a.kind != MemberKind::kGear)
      return Problem(mesh.where, "a", mesh.a + " is a " + ToString(a.kind) + ", not a gear",
                     "a gear (for a rack mesh: the pinion)");
    if (mesh.kind == MeshKind::kRack) {
      if (b.kind != MemberKind::kRack)
        return Problem(mesh.where, "b", mesh.b + " is not a rack", "a [rack.NAME] section");
      if (!a.carrier.empty())
        return Problem(mesh.where, "a", "a rack's pinion on a carrier is not supported",
                       "a pinion on a fixed axis");
      double m = a.module_m;
      if (b.module_m > 0 && m > 0 && std::abs(b.module_m - m) > 1e-9 * m)
        return Problem(
            mesh.where, "b",
            "rack module " + Num(b.module_m) + " m differs from the pinion's " + Num(m) + " m",
            "equal modules (a rack meshes only with its own module)");
      if (m <= 0) m = b.module_m;
      if (m <= 0)
        return Problem(a.where, "module_m", "the pinion of rack " + b.name + " needs a module",
                       "module_m of the pinion or of the rack [m]");
      if (!FirstMeshOfPair(mesh, ia, ib)) return;
      const double r = 0.5 * m * a.teeth;  // pitch radius, Example 2.3: D = m N
      rows_.push_back({{{ib, 1.0}, {ia, -r}}, 0.0, false, -1, "rack mesh " + what, mesh.where});
      return;
    }
    if (b.kind != MemberKind::kGear)
      return Problem(mesh.where, "b", mesh.b + " is a " + ToString(b.kind) + ", not a gear",
                     "a gear; a rack only in a mesh of kind \"rack\"");
    if (a.teeth < 1 || b.teeth < 1) return;  // reported with the member
    // Two gears mesh only with one module (worm: axial module = the wheel's transverse one;
    // bevel: the module at the large end).
    if (a.module_m > 0 && b.module_m > 0 &&
        std::abs(a.module_m - b.module_m) > 1e-9 * std::max(a.module_m, b.module_m))
      return Problem(mesh.where, "b",
                     mesh.b + " has module " + Num(b.module_m) + " m and " + mesh.a + " " +
                         Num(a.module_m) + " m: gears of different modules do not mesh",
                     "equal module_m on both gears of a mesh");
    double s = -1.0;
    switch (mesh.kind) {
      case MeshKind::kExternal:
      case MeshKind::kBevel:
        s = (mesh.kind == MeshKind::kBevel && mesh.bevel_same_sense) ? 1.0 : -1.0;
        break;
      case MeshKind::kInternal: {
        s = 1.0;
        if (a.teeth == b.teeth)
          return Problem(mesh.where, "b",
                         "an internal pair needs a ring with more teeth than "
                         "its pinion; both have " +
                             std::to_string(a.teeth),
                         "z_ring > z_pinion");
        break;
      }
      case MeshKind::kWorm:
        if (a.worm_hand == WormHand::kNone)
          return Problem(mesh.where, "a", mesh.a + " is not a worm",
                         "a gear with worm_hand = \"right\" or \"left\" (teeth = starts)");
        s = a.worm_hand == WormHand::kRight ? 1.0 : -1.0;
        break;
      case MeshKind::kRack:
        break;
    }
    if (mesh.kind != MeshKind::kWorm) {
      for (const TrainMember* g : {&a, &b})
        if (g->worm_hand != WormHand::kNone)
          return Problem(mesh.where, "kind", g->name + " is a worm", "kind = \"worm\"");
    } else if (b.worm_hand != WormHand::kNone) {
      return Problem(mesh.where, "b", "a worm drives a worm wheel, not another worm",
                     "a gear without worm_hand");
    }
    const int c = MeshFrame(mesh, a, b);
    if (c == -2) return;
    if (c >= 0 && mesh.kind == MeshKind::kWorm)
      return Problem(mesh.where, "kind", "a worm pair on a carrier is not supported",
                     "worms on fixed axes");
    if (!FirstMeshOfPair(mesh, ia, ib)) return;
    // z_b (w_b - w_c) - s z_a (w_a - w_c) = 0, Willis (2.7) per mesh.
    const double za = a.teeth, zb = b.teeth;
    Row row{{{ib, zb}, {ia, -s * za}},
            0.0,
            false,
            -1,
            ToString(mesh.kind) + " mesh " + what,
            mesh.where};
    if (c >= 0) {
      row.coeffs.push_back({c, s * za - zb});
      row.label += " (on carrier " + spec_.members[c].name + ")";
    }
    rows_.push_back(std::move(row));
  }

  // Two gears touch at one pitch point: a second mesh of the same pair (say once external,
  // once internal) is a slip of the file, reported at the second mesh.
  bool FirstMeshOfPair(const TrainMesh& mesh, int ia, int ib) {
    const auto [it, fresh] = pair_mesh_.emplace(
        std::minmax(ia, ib), mesh.where.empty() ? mesh.a + "-" + mesh.b : "[" + mesh.where + "]");
    if (!fresh)
      Problem(mesh.where, "b",
              mesh.a + " and " + mesh.b + " already mesh in " + it->second +
                  ": one pair of gears has one mesh",
              "one [mesh.NAME] per pair of members (remove this one)");
    return fresh;
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
    for (const TrainMesh& m : spec_.meshes) AddMesh(m);
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
  std::map<std::pair<int, int>, std::string> pair_mesh_;  // meshed pair -> its mesh
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
