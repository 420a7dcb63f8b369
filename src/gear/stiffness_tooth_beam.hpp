// Private helper of PotentialEnergyStiffness: one tooth as a non-uniform cantilever on an
// elastic gear body (formulas in include/tehl/gear/potential_energy_stiffness.hpp).
#pragma once

#include <vector>

#include "gear/stiffness_tooth_geometry.hpp"
#include "tehl/gear/potential_energy_stiffness.hpp"

namespace tehl::internal {

// Gauss-Legendre rule on [-1, 1]: nodes and weights, by Newton iteration on P_n.
struct GaussLegendreRule {
  explicit GaussLegendreRule(int n);
  std::vector<double> nodes, weights;
};

// Sainsot, Velex & Duverger (2004) fitted coefficient X*(h_f, theta_f), one row of their table.
struct FoundationFit {
  double a, b, c, d, e, f;
  double Evaluate(double h_f, double theta_f) const {
    return a / (theta_f * theta_f) + b * h_f * h_f + c * h_f / theta_f + d / theta_f + e * h_f + f;
  }
};

class StiffnessToothBeam {
 public:
  // blank: checked, external, not pointed. face_width_m: common face width L.
  StiffnessToothBeam(const ToothBlank& blank,
                     double face_width_m,
                     const PotentialEnergyStiffness::Options& options);

  // Contact at radius r on the drive flank (clamped to [LowestContactRadius(), r_a]).
  PotentialEnergyStiffness::ToothCompliance Compliance(double r_m) const;
  double LowestContactRadius() const { return contact_radius_; }

  // Dimensionless body parameters of the foundation term, for reports and tests.
  double foundation_h() const { return foundation_h_; }          // h_f = r_f / r_int [-]
  double foundation_theta() const { return foundation_theta_; }  // theta_f [rad]

 private:
  struct Section {
    double thickness;  // t = h_d + h_c [m]
    double offset;     // e = (h_d - h_c) / 2 [m]
  };
  Section SectionAt(double y_m) const;

  StiffnessToothGeometry geometry_;
  GaussLegendreRule rule_;
  double face_width_ = 0;         // L [m]
  double e_bending_ = 0;          // E_e for bending, axial and foundation [Pa]
  double g_shear_ = 0;            // G [Pa]
  double contact_radius_ = 0;     // lowest contact radius max(r_f, r_b,d) [m]
  double start_radius_ = 0;       // where the beam is clamped: r_f, or max(r_f, r_b,d) [m]
  double drive_kink_y_ = 0;       // y where the drive flank leaves its base circle [m]
  double coast_kink_y_ = 0;       // y where the coast flank leaves its base circle [m]
  double foundation_h_ = 0;       // h_f [-]
  double foundation_theta_ = 0;   // theta_f [rad]
  double foundation_offset_ = 0;  // lateral offset of the root-section centre, e_f [m]
  double l_star_ = 0, m_star_ = 0, p_star_ = 0, q_star_ = 0;
};

}  // namespace tehl::internal
