#include "ehl/anderson_mixer.hpp"

#include <Eigen/QR>

namespace tehl::internal {

Eigen::MatrixXd AndersonMixer::Mix(const Eigen::MatrixXd& x_in,
                                   const Eigen::MatrixXd& g_in,
                                   double relaxation) {
  const Eigen::Map<const Eigen::VectorXd> x(x_in.data(), x_in.size());
  const Eigen::Map<const Eigen::VectorXd> g(g_in.data(), g_in.size());
  const Eigen::VectorXd f = g - x;
  Eigen::VectorXd next = x + relaxation * f;
  if (have_) {
    dx_.push_back(x - x_);
    df_.push_back(f - f_);
    if (static_cast<int>(dx_.size()) > depth_) {
      dx_.erase(dx_.begin());
      df_.erase(df_.begin());
    }
    const int m = static_cast<int>(df_.size());
    Eigen::MatrixXd dF(f.size(), m), dX(f.size(), m);
    for (int k = 0; k < m; ++k) {
      dF.col(k) = df_[k];
      dX.col(k) = dx_[k];
    }
    const Eigen::VectorXd gamma = dF.colPivHouseholderQr().solve(f);
    if (gamma.allFinite()) next -= (dX + relaxation * dF) * gamma;
  }
  have_ = true;
  x_ = x;
  f_ = f;
  return Eigen::Map<const Eigen::MatrixXd>(next.data(), x_in.rows(), x_in.cols());
}

}  // namespace tehl::internal
