// Corner contact: a loaded pair meshes beyond the ends of its path of contact. The teeth in
// contact deflect by the approach x along the line of action, so the next pair touches
// before A (the wheel's tip corner on the pinion's flank) and the leaving pair keeps touching
// after E (the pinion's tip corner on the wheel's flank), wherever the rigid separation of
// corner and flank is below x (the "extended contact" of loaded tooth contact analysis; Munro
// 1967; Kahraman & Blankenship 1999, J. Mech. Des. 121:313). Without it the mesh stiffness
// steps at A and E, and with the approach continuous the mesh force steps with it: a
// dynamic load factor of k_double / k_single at any speed, also as the speed goes to zero.
//
// The separation is exact involute geometry. In the plane of the gears, every involute of a
// base circle r_b unwound the same way is fixed by where it crosses the line of action, its
// roll length u; the involute through a point Q at radius r and polar angle phi (T1 at
// phi = pi/2, the line of action running in +x at height r_b) has
//     u(Q) = sqrt(r^2 - r_b^2) - r_b (phi + acos(r_b / r) - pi/2),
// and involutes of one base circle are parallel curves u apart along their common normals,
// which are the tangents to the base circle: a rotation of the gear by dtheta moves its flank
// by r_b dtheta along them, the unit of the transmission error x. So the separation of a
// corner from the mating flank, in units of x, is the difference between the corner's u and
// the flank's. Before A the wheel has turned back by s / r_b2 from its position at A (its
// corner on its tip circle), after E the pinion has turned on by (s - g_alpha) / r_b1.
#pragma once

#include "tehl/gear/gear_pair.hpp"

namespace tehl {

class CornerContact {
 public:
  // The flank pair `flank` of `pair` (drive: normal operation). The extension on each side
  // ends where the separation reaches `max_gap_m` [m] > 0 or where the point of the mating
  // flank the corner would touch leaves its involute (below its form circle; external gears).
  CornerContact(const GearPair& pair, Flank flank, double max_gap_m);

  // Separation between the corner and the mating flank of the pair at path coordinate s
  // [m] (s < 0 before A, s > g_alpha after E); 0 on [0, g_alpha]; +infinity beyond the
  // extension. [m]
  double GapAt(double s_m) const;
  double before_m() const { return before_m_; }  // extension before A [m], >= 0
  double after_m() const { return after_m_; }    // extension after E [m], >= 0

 private:
  // Rigid separations without the extension limits, and the radius (about the centre of the
  // gear whose flank is touched) of the point the corner would touch. [m]
  double GapBeforeA(double s_m, double* foot_radius_m) const;
  double GapAfterE(double s_m, double* foot_radius_m) const;
  double Extent(bool before, double max_gap_m) const;

  double rb1_ = 0, rb2_ = 0, tangent_ = 0, rho_a_ = 0, length_ = 0;
  double form1_ = 0, form2_ = 0;  // form radii of the pinion and an external wheel [m]
  bool internal_ = false;
  double before_m_ = 0, after_m_ = 0;
};

}  // namespace tehl
