// Members that the two-term relations of a train tie together (a mesh on fixed axes, a shaft,
// a rack on its pinion) turn in fixed proportion: w_j = factor_j u_g, with u_g the speed of
// one member of the group (its factor is 1). The factors are products of tooth ratios along those
// relations, exact to a few ulps however large the ratio, so a chain of many stages keeps every
// speed to round-off; only the relations of three members (a mesh riding on a carrier, Willis) are
// left to a linear system, and it has one unknown per group. A loop of two-term relations
// whose product disagrees with the factor already found (three external gears in a
// triangle) holds its group at rest. Private to src/drive.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "drive/train_mesh_rows.hpp"

namespace tehl::internal {

struct MemberGroups {
  int count = 0;               // number of groups
  std::vector<int> group;      // per member: its group, 0 .. count-1
  std::vector<double> factor;  // per member: w_member / u_group [-] (rack: [m/rad])
  std::vector<bool> locked;    // per group: a loop of relations forces u_group = 0
  std::vector<int> kept;       // the rows (indices into `rows`) of three or more members
};

// Groups the members of the first `kinematic` rows of `rows` (meshes and shafts only).
MemberGroups GroupMembers(int members, const std::vector<TrainRow>& rows, int kinematic);

// The train's system in the group speeds: the rows of three or more members, a row u = 0
// per group a loop locks (the kinematic rows), then one row per input. Column g is scaled
// by its largest entry in the kinematic rows (y_g = scale_g u_g) and every row to unit
// norm, so the rank tests see a system of unit scale whatever the train's ratio. The solve
// takes the driven (and locked) groups as known and solves the others per component (the
// groups the kept rows tie together), so a slow group is not blurred by the round-off of a
// fast one.
class GroupSystem {
 public:
  // `rows`: the kinematic rows (meshes, shafts) first, then the inputs.
  GroupSystem(int members, const std::vector<TrainRow>& rows);

  const MemberGroups& groups() const { return groups_; }
  int rows() const { return static_cast<int>(a_.rows()); }
  int kinematic_rows() const { return kinematic_rows_; }
  // The row of `rows` (the constructor's) behind input row r >= kinematic_rows().
  int input_row(int r) const { return input_rows_[r - kinematic_rows_]; }

  int Rank(int top) const;               // rank of the first `top` rows
  Eigen::VectorXd Solve(int top) const;  // least squares of the first `top` rows
  std::vector<double> Speeds(const Eigen::VectorXd& y) const;  // w_j = factor_j y_g / scale_g
  Eigen::MatrixXd FreeMotions() const;  // orthonormal kernel of the kinematic rows (columns)
  Eigen::MatrixXd Kernel() const;       // kernel of the whole system (columns)

 private:
  Eigen::VectorXd Rest(Eigen::VectorXd y) const;

  MemberGroups groups_;
  std::vector<int> component_;  // per group: the groups the kept rows tie it to share one
  Eigen::MatrixXd a_;
  Eigen::VectorXd b_;
  Eigen::VectorXd scale_;
  int kinematic_rows_ = 0;
  std::vector<int> input_rows_;
};

}  // namespace tehl::internal
