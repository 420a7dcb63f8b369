// Where the involute of an undercut gear begins. When the generating rack's straight flank
// ends beyond the interference point T of the base circle ((h_F0 - x) m_n > r sin^2 alpha_t),
// the rack's tip, rounded by its fillet of radius rho_fP m_n, sweeps through the tooth as the
// gear turns and cuts the involute away from the base circle up to a roll length s_u along the
// line of action. The flank's involute (and a mating tip that meets it) starts at
// r_u = sqrt(r_b^2 + s_u^2), its form circle. Solved in the transverse plane (a helical gear's
// fillet is taken with its normal radius).
#pragma once

namespace tehl {

struct RackCut {
  double pitch_radius_m = 0;              // r [m]
  double pressure_angle_rad = 0;          // transverse pressure angle of this flank alpha_t [rad]
  double normal_pressure_angle_rad = 0;   // alpha_n, for the end of the rack's straight flank
                                          //   h_F0 = h_fP - rho_fP (1 - sin alpha_n); 0 = alpha_t
                                          //   (spur) [rad]
  double module_m = 0;                    // normal module m_n [m]
  double profile_shift = 0;               // x [-]
  double dedendum_coefficient = 1.25;     // rack dedendum h_fP / m_n [-]
  double root_fillet_coefficient = 0.38;  // rack tip radius rho_fP / m_n [-]
};

// s_u [m]: the roll length from T up to which the rack's tip cuts the involute; 0 for a gear
// that is not undercut.
double UndercutRollLength(const RackCut& c);

}  // namespace tehl
