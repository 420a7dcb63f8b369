// Anderson acceleration of a fixed-point iteration x -> g(x) (Walker & Ni 2011, "Anderson
// acceleration for fixed-point iterations", SIAM J. Numer. Anal. 49:1715, type II). Private
// to src/ehl.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace tehl::internal {

// Depth m; each step damped by `relaxation`.
class AndersonMixer {
 public:
  explicit AndersonMixer(int depth) : depth_(depth) {}
  // The next iterate from the current one and its image.
  Eigen::MatrixXd Mix(const Eigen::MatrixXd& x, const Eigen::MatrixXd& g, double relaxation);

 private:
  int depth_;
  bool have_ = false;
  Eigen::VectorXd x_, f_;
  std::vector<Eigen::VectorXd> dx_, df_;
};

}  // namespace tehl::internal
