// Kinematics of the contact point along the path of contact of one flank pair
// (DESIGN.md section 2, VALIDATION.md section 5 conventions).
//
// s is measured along the line of action from A (start of active profile on the pinion,
// s = 0) to E (pinion tip, s = g_alpha). The contact point moves at r_b1 w1, so the time
// since A is t = s / (r_b1 w1) and a mesh period is p_b / (r_b1 w1). Radii of curvature
// are the involute roll distances: rho1 = T1P, rho2 = T2P (external: T1T2 - rho1; internal:
// T1T2 + rho1, the ring's flank is concave). Surface speeds u_i = w_i rho_i both point the
// same way (rolling), um = (u1 + u2)/2, SRR = (u1 - u2)/um, sliding speed u1 - u2.
// Identities: u1 - u2 = (w1 + w2)(P - C) external, (w1 - w2)(P - C) internal.
#pragma once

#include <vector>

#include "tehl/gear/gear_pair.hpp"

namespace tehl {

struct ContactPoint {
  double s_m = 0;               // distance from A along the line of action [m]
  double position_m = 0;        // distance from T1 [m]
  double time_s = 0;            // t = s / (r_b1 w1) [s]
  double rho1_m = 0;            // radius of curvature of the pinion flank [m]
  double rho2_m = 0;            // radius of curvature of the wheel flank (ring: concave) [m]
  double reduced_radius_m = 0;  // R: 1/R = 1/rho1 + 1/rho2 (ring: 1/rho1 - 1/rho2) [m]
  double r1_m = 0;              // contact radius on the pinion, sqrt(r_b1^2 + rho1^2) [m]
  double r2_m = 0;              // contact radius on the wheel [m]
  double u1_m_s = 0;            // pinion surface speed w1 rho1 [m/s]
  double u2_m_s = 0;            // wheel surface speed w2 rho2 [m/s]
  double um_m_s = 0;            // entrainment speed (u1 + u2)/2 [m/s]
  double srr = 0;               // slide-to-roll ratio (u1 - u2)/um [-]
  double sliding_m_s = 0;       // u1 - u2 [m/s]
  int pairs_in_contact = 0;     // tooth pairs carrying load at this instant [-]
};

class PathOfContact {
 public:
  // pinion_speed_rad_s > 0 [rad/s]; the flank pair in mesh (drive: normal operation).
  PathOfContact(const GearPair& pair, double pinion_speed_rad_s, Flank flank = Flank::kDrive);

  const LineOfAction& line() const { return line_; }
  bool internal() const { return internal_; }
  double length_m() const { return line_.length_m; }            // g_alpha [m]
  double base_pitch_m() const { return line_.base_pitch_m; }    // p_b [m]
  double contact_ratio() const { return line_.contact_ratio; }  // eps_alpha [-]
  double pinion_speed_rad_s() const { return w1_; }             // w1 [rad/s]
  double wheel_speed_rad_s() const { return w2_; }              // w2 = w1 z1 / z2 [rad/s]
  double contact_speed_m_s() const { return line_.pinion_base_radius_m * w1_; }  // r_b1 w1
  double mesh_period_s() const { return base_pitch_m() / contact_speed_m_s(); }  // [s]
  double duration_s() const { return length_m() / contact_speed_m_s(); }         // A to E [s]
  // s of the named points: A = 0, B, C (pitch point), D, E = g_alpha [m].
  double s_b_m() const { return line_.b_m - line_.a_m; }
  double s_c_m() const { return line_.c_m - line_.a_m; }
  double s_d_m() const { return line_.d_m - line_.a_m; }

  // The contact state at s (extrapolates outside [0, g_alpha]; pairs_in_contact then
  // counts the others only).
  ContactPoint At(double s_m) const;
  // s of every pair in contact at the instant the tracked pair is at s: s + j p_b in
  // [0, g_alpha] for integer j, ascending; includes s itself when it is on the path.
  std::vector<double> SimultaneousContacts(double s_m) const;

 private:
  LineOfAction line_;
  bool internal_ = false;
  double w1_ = 0, w2_ = 0;
};

}  // namespace tehl
