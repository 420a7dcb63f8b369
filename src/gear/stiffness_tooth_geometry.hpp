// Private helper of the mesh-stiffness methods: the plane geometry of one external tooth with
// possibly different drive and coast pressure angles, in the frame the beam model of the
// potential-energy method needs.
//
// Frame: origin at the gear centre, y along the tooth axis (outwards), x across the tooth,
// the drive flank on the +x side. The tooth axis is the line through the middle of the
// generating rack tooth space at the rolling line, so at the reference circle each side holds
// (pi m / 4 + x m tan alpha_side) of the tooth thickness (for an asymmetric rack with the
// datum where tooth and space are equal, after Kapelevich 2000 and seed 000 section 3.3).
//
// Flank of side s at radius r (involute of its own base circle r_b,s = r_p cos alpha_s):
//   psi_s(r) = (pi/2 + 2 x tan alpha_s) / z + inv alpha_s - inv alpha_s(r),
//   cos alpha_s(r) = r_b,s / r                                 (seed 000 eq. 2.13)
// Below its base circle a flank is taken as radial, psi_s(r) = psi_s(r_b,s) (the usual
// assumption of the potential-energy method, Tian 2004; Chaari et al. 2009).
#pragma once

#include <cmath>

#include "tehl/gear/mesh_stiffness.hpp"

namespace tehl::internal {

// Involute function inv(a) = tan(a) - a (seed 000 eq. 2.10).
inline double Involute(double a_rad) { return std::tan(a_rad) - a_rad; }

enum class FlankSide { kDrive, kCoast };

class StiffnessToothGeometry {
 public:
  // blank must be external and already checked by CheckToothBlank().
  explicit StiffnessToothGeometry(const ToothBlank& blank);

  double pitch_radius_m() const { return pitch_radius_; }
  double root_radius_m() const { return root_radius_; }  // r_f = r_p - (h_fP/m - x) m
  double tip_radius_m() const { return tip_radius_; }
  double base_radius_m(FlankSide s) const { return side(s).base_radius; }
  double pressure_angle_rad(FlankSide s) const { return side(s).pressure_angle; }

  // psi_s(r): polar angle of the flank of side s from the tooth axis at radius r [rad].
  double HalfAngle(FlankSide s, double r_m) const;
  // Lateral distance of the flank of side s from the tooth axis at axial coordinate y [m]
  // (the flank point with r cos psi_s(r) = y, then r sin psi_s(r)).
  double HalfWidthAtAxial(FlankSide s, double y_m) const;
  // Polar angle, from the tooth axis, of the junction of the root fillet of side s with the
  // root circle [rad]: the rack tip rounding of radius rho_fP with centre at depth
  // (h_fP - rho_fP) m below the datum generates it, so
  //   theta_f,s = 2 [pi/4 + (h_fP/m - rho_fP/m) tan alpha_s + (rho_fP/m) / cos alpha_s] / z
  // (the profile shift cancels). Sainsot et al. (2004) use theta_f = mean of both sides.
  double RootFilletAngle(FlankSide s) const;

 private:
  struct Side {
    double pressure_angle = 0;   // alpha_s [rad]
    double base_radius = 0;      // r_b,s [m]
    double involute_offset = 0;  // (pi/2 + 2 x tan alpha_s)/z + inv alpha_s [rad]
  };
  const Side& side(FlankSide s) const { return s == FlankSide::kDrive ? drive_ : coast_; }

  int teeth_ = 0;
  double dedendum_coefficient_ = 0, fillet_coefficient_ = 0;
  double pitch_radius_ = 0, root_radius_ = 0, tip_radius_ = 0;
  Side drive_, coast_;
};

}  // namespace tehl::internal
