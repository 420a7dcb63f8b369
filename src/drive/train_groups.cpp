// Groups of members tied by two-term relations and the system in their speeds
// (train_groups.hpp).
#include "drive/train_groups.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace tehl::internal {
namespace {

// Two products of tooth ratios along different paths that agree to this relative
// difference are one ratio: a path of 20 stages rounds to about 1e-14 [-].
constexpr double kLoopTolerance = 1e-11;
constexpr double kRankTolerance = 1e-10;  // pivot threshold on unit-norm rows [-]
constexpr double kRestFraction = 1e-12;   // |y| below this times its component's max is rest
constexpr double kCancelled = 1e-12;      // a coefficient this small against its terms is 0 [-]

Eigen::MatrixXd KernelOf(const Eigen::MatrixXd& m) {
  if (m.rows() == 0) return Eigen::MatrixXd::Identity(m.cols(), m.cols());
  Eigen::FullPivLU<Eigen::MatrixXd> lu(m);
  lu.setThreshold(kRankTolerance);
  return lu.rank() == m.cols() ? Eigen::MatrixXd::Zero(m.cols(), 0) : Eigen::MatrixXd(lu.kernel());
}

}  // namespace

MemberGroups GroupMembers(int members, const std::vector<TrainRow>& rows, int kinematic) {
  std::vector<int> group(members);
  std::vector<double> factor(members, 1.0);
  std::vector<std::vector<int>> in_group(members);
  std::vector<bool> locked(members, false);
  for (int j = 0; j < members; ++j) {
    group[j] = j;
    in_group[j] = {j};
  }
  MemberGroups out;
  for (int r = 0; r < kinematic; ++r) {
    // The row's coefficients per member (a zero one, e.g. the carrier of a bevel pair of
    // equal teeth turning the same way, drops out).
    std::map<int, double> c;
    for (auto [j, v] : rows[r].coeffs) c[j] += v;
    for (auto it = c.begin(); it != c.end();) it = it->second == 0.0 ? c.erase(it) : ++it;
    if (c.size() != 2) {
      out.kept.push_back(r);
      continue;
    }
    const auto [i, ci] = *c.begin();
    const auto [j, cj] = *c.rbegin();
    const double ratio = -ci / cj;  // w_j = ratio w_i
    const int gi = group[i], gj = group[j];
    if (gi == gj) {
      // A loop: the row repeats the group's proportion, or it holds the group at rest.
      const double want = ratio * factor[i];
      if (std::abs(factor[j] - want) > kLoopTolerance * std::abs(factor[j])) locked[gi] = true;
      continue;
    }
    // Merge the smaller group into the larger one: u_gj = (ratio factor_i / factor_j) u_gi,
    // or the other way round.
    const bool into_i = in_group[gi].size() >= in_group[gj].size();
    const int keep = into_i ? gi : gj, gone = into_i ? gj : gi;
    const double scale = into_i ? ratio * factor[i] / factor[j] : factor[j] / (ratio * factor[i]);
    for (int m : in_group[gone]) {
      factor[m] *= scale;
      group[m] = keep;
      in_group[keep].push_back(m);
    }
    in_group[gone].clear();
    locked[keep] = locked[keep] || locked[gone];
  }
  // Number the groups 0 .. count-1 in the order of their first member.
  std::vector<int> number(members, -1);
  out.group.resize(members);
  for (int j = 0; j < members; ++j) {
    int& n = number[group[j]];
    if (n < 0) {
      n = out.count++;
      out.locked.push_back(locked[group[j]]);
    }
    out.group[j] = n;
  }
  out.factor = std::move(factor);
  return out;
}

GroupSystem::GroupSystem(int members, const std::vector<TrainRow>& rows) {
  int kinematic = 0;
  while (kinematic < static_cast<int>(rows.size()) && !rows[kinematic].input) ++kinematic;
  groups_ = GroupMembers(members, rows, kinematic);
  const int count = groups_.count;
  std::vector<Eigen::RowVectorXd> reduced;
  std::vector<double> rhs;
  for (int r : groups_.kept) {
    Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(count);
    Eigen::RowVectorXd size = Eigen::RowVectorXd::Zero(count);  // the terms before they cancel
    for (auto [j, v] : rows[r].coeffs) {
      row(groups_.group[j]) += v * groups_.factor[j];
      size(groups_.group[j]) += std::abs(v * groups_.factor[j]);
    }
    // Members of one group in one row (a planet meshing a gear its carrier's shaft turns)
    // may cancel to round-off: then the group is not in the row.
    for (int g = 0; g < count; ++g)
      if (std::abs(row(g)) <= kCancelled * size(g)) row(g) = 0.0;
    reduced.push_back(row);
    rhs.push_back(0.0);
  }
  for (int g = 0; g < count; ++g)
    if (groups_.locked[g]) {
      reduced.push_back(Eigen::RowVectorXd::Unit(count, g));
      rhs.push_back(0.0);
    }
  kinematic_rows_ = static_cast<int>(reduced.size());
  for (int r = kinematic; r < static_cast<int>(rows.size()); ++r) {
    const int j = rows[r].member;
    reduced.push_back(groups_.factor[j] * Eigen::RowVectorXd::Unit(count, groups_.group[j]));
    rhs.push_back(rows[r].rhs);
    input_rows_.push_back(r);
  }
  const int n = static_cast<int>(reduced.size());
  a_ = Eigen::MatrixXd::Zero(n, count);
  b_ = Eigen::VectorXd::Zero(n);
  for (int r = 0; r < n; ++r) {
    a_.row(r) = reduced[r];
    b_(r) = rhs[r];
  }
  // A group's scale comes from the meshes that tie it to others (its input row, when it has
  // one, is a row of its own): the sun at the end of a 1e12 reducer meets its planet with
  // an entry z_sun w_sun / w_p0 = 5e-11 that must not fall under the rank threshold.
  scale_ = Eigen::VectorXd::Ones(count);
  for (int g = 0; g < count; ++g) {
    double largest = kinematic_rows_ ? a_.col(g).head(kinematic_rows_).cwiseAbs().maxCoeff() : 0;
    if (largest == 0 && n) largest = a_.col(g).cwiseAbs().maxCoeff();
    if (largest > 0) {
      scale_(g) = largest;
      a_.col(g) /= largest;
    }
  }
  // Groups the kept rows tie together share a component: rest is judged within it.
  component_.resize(count);
  for (int g = 0; g < count; ++g) component_[g] = g;
  const auto root = [&](int g) {
    while (component_[g] != g) g = component_[g];
    return g;
  };
  for (size_t r = 0; r < groups_.kept.size(); ++r) {
    int first = -1;
    for (int g = 0; g < count; ++g) {
      if (a_(r, g) == 0.0) continue;
      if (first < 0)
        first = root(g);
      else
        component_[root(g)] = first;
    }
  }
  for (int g = 0; g < count; ++g) component_[g] = root(g);
  for (int r = 0; r < n; ++r) {
    const double norm = a_.row(r).norm();
    if (norm > 0) {
      a_.row(r) /= norm;
      b_(r) /= norm;
    }
  }
}

int GroupSystem::Rank(int top) const {
  if (top == 0) return 0;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(a_.topRows(top));
  lu.setThreshold(kRankTolerance);
  return static_cast<int>(lu.rank());
}

// Scaled group speeds below kRestFraction of the largest of their component are round-off
// of rest (a held ring's planet mesh, say); a sub-train apart is no measure of them.
Eigen::VectorXd GroupSystem::Rest(Eigen::VectorXd y) const {
  std::vector<double> largest(y.size(), 0.0);
  for (int g = 0; g < y.size(); ++g)
    largest[component_[g]] = std::max(largest[component_[g]], std::abs(y(g)));
  for (int g = 0; g < y.size(); ++g)
    if (std::abs(y(g)) < kRestFraction * largest[component_[g]]) y(g) = 0.0;
  return y;
}

// The rows of one group only (inputs, locked loops) fix it outright; the others follow from
// the kept rows, solved per component with the fixed groups on the right-hand side, so that
// neither a fast sub-train beside it nor a fast input in its own component blurs a slow
// group by their round-off.
Eigen::VectorXd GroupSystem::Solve(int top) const {
  const int count = groups_.count;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(count);
  std::vector<bool> known(count, false);
  const int kept = static_cast<int>(groups_.kept.size());
  for (int r = kept; r < top; ++r) {
    int g = 0;
    a_.row(r).cwiseAbs().maxCoeff(&g);
    if (known[g]) continue;  // a repeat, reported by the rank test
    y(g) = b_(r) / a_(r, g);
    known[g] = true;
  }
  for (int c = 0; c < count; ++c) {
    if (component_[c] != c) continue;
    std::vector<int> unknown, fixed, rows;
    for (int g = 0; g < count; ++g)
      if (component_[g] == c) (known[g] ? fixed : unknown).push_back(g);
    if (unknown.empty()) continue;
    for (int r = 0; r < std::min(kept, top); ++r)
      if (std::any_of(unknown.begin(), unknown.end(), [&](int g) { return a_(r, g) != 0.0; }))
        rows.push_back(r);
    if (rows.empty()) continue;
    Eigen::MatrixXd m(rows.size(), unknown.size());
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows.size());
    for (size_t i = 0; i < rows.size(); ++i) {
      for (size_t k = 0; k < unknown.size(); ++k) m(i, k) = a_(rows[i], unknown[k]);
      for (int g : fixed) rhs(i) -= a_(rows[i], g) * y(g);
    }
    const Eigen::VectorXd x = m.completeOrthogonalDecomposition().solve(rhs);
    for (size_t k = 0; k < unknown.size(); ++k) y(unknown[k]) = x(k);
  }
  return Rest(y);
}

std::vector<double> GroupSystem::Speeds(const Eigen::VectorXd& y) const {
  std::vector<double> w(groups_.group.size());
  for (size_t j = 0; j < w.size(); ++j) {
    const int g = groups_.group[j];
    w[j] = y(g) == 0.0 ? 0.0 : groups_.factor[j] * (y(g) / scale_(g));
  }
  return w;
}

Eigen::MatrixXd GroupSystem::FreeMotions() const {
  Eigen::MatrixXd free = KernelOf(a_.topRows(kinematic_rows_));
  if (free.cols() > 0) {
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(free);
    free = qr.householderQ() * Eigen::MatrixXd::Identity(free.rows(), free.cols());
  }
  return free;
}

Eigen::MatrixXd GroupSystem::Kernel() const { return KernelOf(a_); }

}  // namespace tehl::internal
