#include "gear/stiffness_tooth_beam.hpp"

#include <algorithm>
#include <cmath>

#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {
namespace {

// Sainsot, Velex & Duverger (2004), Table 1: X* = A/theta_f^2 + B h_f^2 + C h_f/theta_f
// + D/theta_f + E h_f + F for X = L, M, P, Q (published constants).
constexpr FoundationFit kLStar{-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045};
constexpr FoundationFit kMStar{60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086};
constexpr FoundationFit kPStar{-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236};
constexpr FoundationFit kQStar{-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904};

}  // namespace

GaussLegendreRule::GaussLegendreRule(int n) : nodes(n), weights(n) {
  TEHL_ASSERT(n >= 1, "Gauss-Legendre rule needs n >= 1");
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Initial guess of the i-th root (Tricomi), then Newton on P_n.
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = x;  // P_0, P_1
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      // p1 = P_n(x), p0 = P_{n-1}(x); P_n'(x) = n (x P_n - P_{n-1}) / (x^2 - 1).
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    nodes[i] = -x;
    nodes[n - 1 - i] = x;
    weights[i] = weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}

StiffnessToothBeam::StiffnessToothBeam(const ToothBlank& blank,
                                       double face_width_m,
                                       const PotentialEnergyStiffness::Options& options)
    : geometry_(blank), rule_(options.quadrature_points), face_width_(face_width_m) {
  const double e = blank.youngs_modulus_pa, nu = blank.poisson_ratio;
  e_bending_ = options.plane_strain ? e / (1.0 - nu * nu) : e;
  g_shear_ = e / (2.0 * (1.0 + nu));

  const double r_f = geometry_.root_radius_m();
  contact_radius_ = std::max(r_f, geometry_.base_radius_m(FlankSide::kDrive));
  start_radius_ = options.start_at_root_circle ? r_f : contact_radius_;
  auto kink = [&](FlankSide side) {
    const double r_b = geometry_.base_radius_m(side);
    return r_b * std::cos(geometry_.HalfAngle(side, r_b));
  };
  drive_kink_y_ = kink(FlankSide::kDrive);
  coast_kink_y_ = kink(FlankSide::kCoast);

  const double r_int = blank.bore_radius_m > 0 ? blank.bore_radius_m : 0.5 * r_f;
  foundation_h_ = r_f / r_int;
  const double theta_d = geometry_.RootFilletAngle(FlankSide::kDrive);
  const double theta_c = geometry_.RootFilletAngle(FlankSide::kCoast);
  foundation_theta_ = 0.5 * (theta_d + theta_c);
  foundation_offset_ = 0.5 * r_f * (std::sin(theta_d) - std::sin(theta_c));
  l_star_ = kLStar.Evaluate(foundation_h_, foundation_theta_);
  m_star_ = kMStar.Evaluate(foundation_h_, foundation_theta_);
  p_star_ = kPStar.Evaluate(foundation_h_, foundation_theta_);
  q_star_ = kQStar.Evaluate(foundation_h_, foundation_theta_);
}

StiffnessToothBeam::Section StiffnessToothBeam::SectionAt(double y_m) const {
  const double h_d = geometry_.HalfWidthAtAxial(FlankSide::kDrive, y_m);
  const double h_c = geometry_.HalfWidthAtAxial(FlankSide::kCoast, y_m);
  return {h_d + h_c, 0.5 * (h_d - h_c)};
}

PotentialEnergyStiffness::ToothCompliance StiffnessToothBeam::Compliance(double r_m) const {
  const double tip = geometry_.tip_radius_m();
  TEHL_ASSERT(r_m >= contact_radius_ * (1 - 1e-9) && r_m <= tip * (1 + 1e-9),
              "contact radius outside the involute of the drive flank");
  const double r = std::clamp(r_m, contact_radius_, tip);

  // Contact point and load angle a1 = alpha(r) - psi_d(r).
  const double psi_k = geometry_.HalfAngle(FlankSide::kDrive, r);
  const double alpha_k = std::acos(std::min(1.0, geometry_.base_radius_m(FlankSide::kDrive) / r));
  const double a1 = alpha_k - psi_k;
  const double cos_a1 = std::cos(a1), sin_a1 = std::sin(a1);
  const double x_p = r * std::sin(psi_k), y_p = r * std::cos(psi_k);
  const double y_s =
      start_radius_ * std::cos(geometry_.HalfAngle(FlankSide::kDrive, start_radius_));

  PotentialEnergyStiffness::ToothCompliance c;
  // Integrate over the smooth pieces: a flank has a kink where it leaves its base circle.
  double breaks[4] = {y_s, 0, 0, 0};
  int n_breaks = 1;
  for (double kink :
       {std::min(drive_kink_y_, coast_kink_y_), std::max(drive_kink_y_, coast_kink_y_)}) {
    if (kink > breaks[n_breaks - 1] && kink < y_p) breaks[n_breaks++] = kink;
  }
  breaks[n_breaks] = y_p;
  const int pieces = n_breaks;
  const double l = face_width_;
  for (int piece = 0; piece < pieces; ++piece) {
    const double lo = breaks[piece], hi = breaks[piece + 1];
    // y = lo + (hi - lo) (3 t^2 - 2 t^3), t in [0, 1], clusters the points at both ends:
    // just above a base circle a flank's half width goes like (y - lo)^(3/2), smooth in t,
    // and near a thin tip the integrand ~ 1/h^3 grows steeply.
    for (std::size_t q = 0; q < rule_.nodes.size(); ++q) {
      const double t = 0.5 * (1.0 + rule_.nodes[q]);
      const double y = lo + (hi - lo) * t * t * (3.0 - 2.0 * t);
      const double w = 0.5 * rule_.weights[q] * 6.0 * (hi - lo) * t * (1.0 - t);
      const Section s = SectionAt(y);
      const double area = s.thickness * l;
      const double inertia = s.thickness * s.thickness * s.thickness * l / 12.0;
      const double arm = (y_p - y) * cos_a1 - (x_p - s.offset) * sin_a1;
      c.bending += w * arm * arm / (e_bending_ * inertia);
      c.shear += w * 1.2 * cos_a1 * cos_a1 / (g_shear_ * area);
      c.axial += w * sin_a1 * sin_a1 / (e_bending_ * area);
    }
  }

  // Fillet foundation (Sainsot et al. 2004).
  const double r_f = geometry_.root_radius_m();
  const double s_f = 2.0 * r_f * foundation_theta_;
  const double u_f = y_p - (x_p - foundation_offset_) * std::tan(a1) - r_f;
  const double ratio = u_f / s_f;
  const double tan_a1 = std::tan(a1);
  c.foundation =
      cos_a1 * cos_a1 / (e_bending_ * l) *
      (l_star_ * ratio * ratio + m_star_ * ratio + p_star_ * (1.0 + q_star_ * tan_a1 * tan_a1));
  return c;
}

}  // namespace tehl::internal
