// Torques by virtual work (train_torques.hpp): one equation per free motion of the meshes
// and shafts, unknowns the output torque and the held members' reactions.
#include "tehl/drive/train_torques.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace tehl {

TrainTorques SolveTrainTorques(const GearTrainSpec& spec,
                               const TrainSolution& solution,
                               double input_torque) {
  TrainTorques t;
  const int n = static_cast<int>(spec.members.size());
  t.torque.assign(n, std::nullopt);
  std::vector<int> driven, unknown;  // unknown: the output, then the held members
  for (int j = 0; j < n; ++j) {
    const auto& speed = spec.members[j].speed;
    if (speed && *speed != 0.0) driven.push_back(j);
  }
  if (driven.size() != 1) {
    t.message =
        "torques need exactly one driven member; this train has " + std::to_string(driven.size());
    return t;
  }
  t.input = driven.front();
  t.output = spec.Index(spec.output);
  if (t.output < 0) {
    t.message = "no [train] output to carry the load";
    return t;
  }
  if (t.output == t.input) {
    t.message = "the output is the driven member";
    return t;
  }
  const auto& out_speed = spec.members[t.output].speed;
  if (out_speed && *out_speed == 0.0) {
    t.message = "the output " + spec.output + " is held: it does no work";
    return t;
  }
  unknown.push_back(t.output);
  for (int j = 0; j < n; ++j) {
    const auto& speed = spec.members[j].speed;
    if (speed && *speed == 0.0) unknown.push_back(j);
  }
  const int k = static_cast<int>(solution.free_motions.size());
  const int u = static_cast<int>(unknown.size());
  Eigen::MatrixXd a(k, u);
  Eigen::VectorXd b(k);
  for (int r = 0; r < k; ++r) {
    const std::vector<double>& v = solution.free_motions[r];
    for (int c = 0; c < u; ++c) a(r, c) = v[unknown[c]];
    b(r) = -input_torque * v[t.input];
  }
  // Each unknown's column at unit norm: an output many stages from the input moves by a
  // tiny fraction of what a held reaction near the input would, and its torque is as large.
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(u);
  for (int c = 0; c < u; ++c) {
    const double norm = a.col(c).norm();
    if (norm > 0) {
      scale(c) = norm;
      a.col(c) /= norm;
    }
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  qr.setThreshold(1e-10);
  if (qr.rank() < u) {
    t.message =
        "the torques are not fixed by the kinematics alone (the output and the held "
        "members share a motion)";
    return t;
  }
  const Eigen::VectorXd scaled = qr.solve(b);
  if ((a * scaled - b).norm() > 1e-9 * (b.norm() + (a.cwiseAbs() * scaled.cwiseAbs()).norm())) {
    t.message = "no torques balance the input (the output does not move with it)";
    return t;
  }
  const Eigen::VectorXd tau = scaled.cwiseQuotient(scale);
  t.torque[t.input] = input_torque;
  for (int c = 0; c < u; ++c)
    t.torque[unknown[c]] = std::abs(scaled(c)) < 1e-12 * b.norm() ? 0.0 : tau(c);
  double power = 0;
  for (int j = 0; j < n; ++j)
    if (t.torque[j]) power += *t.torque[j] * solution.speed[j];
  const double in_power = std::abs(input_torque * solution.speed[t.input]);
  t.power_residual = in_power > 0 ? std::abs(power) / in_power : 0.0;
  t.solved = true;
  return t;
}

}  // namespace tehl
