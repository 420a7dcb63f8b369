// Groups of members tied by two-term relations and the system in their speeds
// (train_groups.hpp).
#include "drive/train_groups.hpp"

#include <cmath>
#include <map>

namespace tehl::internal {
namespace {

// Two products of tooth ratios along different paths that agree to this relative
// difference are one ratio: a path of 20 stages rounds to about 1e-14 [-].
constexpr double kLoopTolerance = 1e-11;
constexpr double kRankTolerance = 1e-10;  // pivot threshold on unit-norm rows [-]
constexpr double kRestFraction = 1e-12;   // |y| below this times max |y| is rest [-]
constexpr double kCancelled = 1e-12;      // a coefficient this small against its terms is 0 [-]

// Scaled group speeds below kRestFraction of the largest are round-off of rest.
Eigen::VectorXd Rest(Eigen::VectorXd y) {
  const double largest = y.size() ? y.cwiseAbs().maxCoeff() : 0.0;
  for (double& x : y)
    if (std::abs(x) < kRestFraction * largest) x = 0.0;
  return y;
}

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
    double size = 0;  // the terms before they cancel
    for (auto [j, v] : rows[r].coeffs) {
      row(groups_.group[j]) += v * groups_.factor[j];
      size += std::abs(v * groups_.factor[j]);
    }
    // A row whose members all turn in one proportion cancels to round-off: redundant.
    for (double& x : row)
      if (std::abs(x) <= kCancelled * size) x = 0.0;
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
  scale_ = Eigen::VectorXd::Ones(count);
  for (int g = 0; g < count; ++g) {
    const double largest = n ? a_.col(g).cwiseAbs().maxCoeff() : 0.0;
    if (largest > 0) {
      scale_(g) = largest;
      a_.col(g) /= largest;
    }
  }
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

Eigen::VectorXd GroupSystem::Solve(int top) const {
  if (top == 0) return Eigen::VectorXd::Zero(groups_.count);
  if (top == rows()) return Rest(a_.colPivHouseholderQr().solve(b_));
  return Rest(a_.topRows(top).completeOrthogonalDecomposition().solve(b_.head(top)));
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
