// Contact ratios of involute gears (seed 003, "What is the gear contact ratio?", sections
// 2.1-2.3 and 4.1). Lengths in metres, angles in radians. Pure functions.
#pragma once

namespace tehl {

// Transverse contact ratio of an external pair, seed 003 section 2.1 (1):
//   eps_alpha = [sqrt(ra1^2 - rb1^2) + sqrt(ra2^2 - rb2^2) - a sin(alpha_w)] / p_b,
// p_b = pi m_t cos(alpha_t) the transverse base pitch.
double ExternalTransverseContactRatio(double tip_radius_1_m,
                                      double base_radius_1_m,
                                      double tip_radius_2_m,
                                      double base_radius_2_m,
                                      double center_distance_m,
                                      double working_pressure_angle_rad,
                                      double base_pitch_m);

// Transverse contact ratio of an internal pair (gear 2 is the ring, ra2 its tip radius,
// which is its inner circle), seed 003 section 2.3:
//   eps_alpha = [sqrt(ra1^2 - rb1^2) - sqrt(ra2^2 - rb2^2) + a sin(alpha_w)] / p_b.
double InternalTransverseContactRatio(double tip_radius_1_m,
                                      double base_radius_1_m,
                                      double tip_radius_2_m,
                                      double base_radius_2_m,
                                      double center_distance_m,
                                      double working_pressure_angle_rad,
                                      double base_pitch_m);

// Transverse module and pressure angle of a helical gear (seed 003 section 2.2 (1)):
// m_t = m_n / cos(beta), tan(alpha_t) = tan(alpha_n) / cos(beta).
struct TransverseParameters {
  double module_m = 0;            // m_t [m]
  double pressure_angle_rad = 0;  // alpha_t [rad]
};
TransverseParameters HelicalTransverse(double normal_module_m,
                                       double normal_pressure_angle_rad,
                                       double helix_angle_rad);

// Face (overlap) contact ratio eps_beta = b sin(beta) / (pi m_n) (seed 003 section 2.2 (2)).
double FaceContactRatio(double face_width_m, double helix_angle_rad, double normal_module_m);

// Design limits of seed 003 section 4.1 for the transverse contact ratio.
struct ContactRatioAssessment {
  bool continuous = false;     // eps_alpha >= 1: a new pair engages before the last leaves
  bool below_minimum = false;  // eps_alpha < 1.2, the industrial minimum (1.4 at high speed)
  bool near_integer = false;   // within `band` of an integer >= 1: synchronous mesh impacts
};
ContactRatioAssessment AssessContactRatio(double eps_alpha, double near_integer_band = 0.05);

}  // namespace tehl
