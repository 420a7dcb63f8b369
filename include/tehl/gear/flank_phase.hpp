// The two flank pairs of one mesh: the pair seen from its coast side, and where the coast
// flanks touch when the drive flanks' contacts are known (docs/dynamics.md "Back flanks").
//
// When the wheel drives the pinion back (a dynamic mesh that strikes its back flanks), the
// coast flanks carry the load along their own line of action, with base circles
// K = cos(alpha_tc) / cos(alpha_td) times the drive flanks', their own stiffness, contact
// ratio and path A_c..E_c. Mirrored, a tooth's coast flank is the drive flank of the same
// tooth: CoastSideSpec swaps the two pressure angles, and the drive line, path, stiffness,
// tip corners and relief of GearPair(CoastSideSpec(s)) are those of the coast flanks of
// GearPair(s) (the same tooth blanks, mirrored; every other value is flank-symmetric).
//
// Phase. On a line of action tangent to the pinion's base circle at T1, the involute of a
// flank crosses at the roll length u from T1. Turning the pinion forward by dpsi moves its
// drive crossings away from T1 by r_bd dpsi and its coast crossings towards T1c by
// r_bc dpsi, so for the two flanks of one tooth
//     u_d / r_bd + u_c / r_bc = Theta_b + alpha_wd + alpha_wc,
//     Theta_b = s / r + inv(alpha_td) + inv(alpha_tc)
// (Theta_b: the angle between the base points of the tooth's two involutes, s the arc
// thickness at the reference radius r; alpha_wd + alpha_wc: the angle between T1 and T1c as
// seen from the pinion's centre), for every tooth modulo 2 pi / z1. With the path coordinates
// s_d = u_d - T1A and s_c = u_c - T1A_c, and r_b / p_b = z1 / (2 pi) on both lines:
//     s_c / p_bc = delta - s_d / p_bd  (mod 1),
//     delta = z1 (Theta_b + alpha_wd + alpha_wc) / (2 pi) - T1A / p_bd - T1A_c / p_bc.
// The pinion's rotation alone places the crossings, so delta holds at any backlash; as the
// drive contacts move forward (A to E) the coast contacts run backwards (E_c to A_c).
// Symmetric teeth: delta = 2 s_C / p_b + s_w1 / p_w (s_w1 the pinion's thickness on its
// operating pitch circle, p_w that circle's pitch; mirror symmetry about the centre line).
#pragma once

#include "tehl/gear/gear_pair.hpp"

namespace tehl {

// The pair seen from its coast side: drive and coast pressure angles swapped [-].
GearPairSpec CoastSideSpec(const GearPairSpec& spec);

// delta above, reduced to [0, 1) [-]: the coast pairs sit at s_c = p_bc (delta - s_d / p_bd)
// modulo p_bc when the drive pairs sit at s_d modulo p_bd.
double CoastPhaseOffset(const GearPair& pair);

}  // namespace tehl
